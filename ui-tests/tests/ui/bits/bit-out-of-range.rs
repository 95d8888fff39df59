use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(link = "ethercat.impact67_0.digital_inputs")]
    impact67_0_digital_inputs: u16,
    #[plc(source = "impact67_0_digital_inputs", bit = 16)]
    ls_lift_neg: bool,
}

fn main() {}
