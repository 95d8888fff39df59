use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    digital_inputs: u16,
    #[plc(source = "Digital_Inputs", bit = 0)]
    flag: bool,
}

fn main() {}
