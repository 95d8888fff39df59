use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
#[plc(bus = "tests/bus/press.toml")]
pub struct Gm {
    #[plc(link = "ethercat.impact76_0.digital_inputs", direction = "input")]
    inputs: u16,
}

fn main() {}
