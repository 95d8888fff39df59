use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
#[plc(bus = "tests/bus/press.toml")]
pub struct Gm {
    #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "output")]
    outputs: u16,
}

fn main() {}
