use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    motor__speed: i32,
}

fn main() {}
