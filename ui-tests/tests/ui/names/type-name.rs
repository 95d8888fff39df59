use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    dint: i32,
}

fn main() {}
