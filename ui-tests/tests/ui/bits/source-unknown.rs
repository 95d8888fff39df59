use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    digital_inputs: u16,
    #[plc(source = "digital_input", bit = 0)]
    flag: bool,
}

fn main() {}
