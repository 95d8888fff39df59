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

/// A struct without a bus description has none to hand a host.
#[derive(GlobalMemory, Debug, Clone)]
pub struct NoBus {
    count: u16,
}

fn main() {
    assert_eq!(Gm::VARIABLES.len(), 4);
    // The description as written and its text, which a program module hands its host.
    let bus = Gm::BUS.expect("the struct names a bus description");
    assert_eq!(bus.file, "../examples/bus/tensile_tester.toml");
    assert_eq!(
        bus.text,
        include_str!("../../../examples/bus/tensile_tester.toml")
    );
    assert_eq!(NoBus::BUS, None);
}
