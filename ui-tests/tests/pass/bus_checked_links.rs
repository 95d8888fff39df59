// Links checked against a bus description while compiling: the main example's file, as the
// tensile tester's struct uses it.
use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
#[plc(bus = "../examples/bus/tensile_tester.toml")]
pub struct Gm {
    #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "input")]
    inputs: u16,
    #[plc(link = "ethercat.impact67_0.digital_outputs", direction = "output")]
    outputs: u16,
    // Internal takes the entry's direction; a BOOL entry widens to u8 as an input would not.
    #[plc(link = "ethercat.lamps.green")]
    green: bool,
    #[plc(link = "ethercat.LAMPS.horn", direction = "output")]
    horn: bool,
}

fn main() {
    assert_eq!(Gm::VARIABLES.len(), 4);
}
