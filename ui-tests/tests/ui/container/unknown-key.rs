use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
#[plc(endian = "little")]
pub struct Gm {
    speed: i32,
}

fn main() {}
