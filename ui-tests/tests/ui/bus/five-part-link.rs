use plc_core::GlobalMemory;

// A link of five parts is well formed (`ethercat.<device>.<entry path>`), but no entry of the
// bus description has that path.
#[derive(GlobalMemory)]
#[plc(bus = "tests/bus/press.toml")]
pub struct Gm {
    #[plc(link = "ethercat.impact67_0.digital_inputs.word.low", direction = "input")]
    inputs: u16,
}

fn main() {}
