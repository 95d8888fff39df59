use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
#[plc(bus = "tests/bus/press.toml")]
pub struct Gm {
    #[plc(link = "ethercat.impact67_0.digtal_inputs", direction = "input")]
    inputs: u16,
}

fn main() {}
