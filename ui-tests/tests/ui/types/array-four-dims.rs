use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    grid: [[[[u8; 2]; 2]; 2]; 2],
}

fn main() {}
