use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(direction = "input")]
    inputs: u16,
    #[plc(source = "inputs", bit = 0, direction = "output")]
    lamp: bool,
}

fn main() {}
