use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    größe: i32,
}

fn main() {}
