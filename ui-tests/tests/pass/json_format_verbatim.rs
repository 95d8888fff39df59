// The example variables of the JSON variable-list format exactly as its JSON declares them (types, links, descriptions,
// max_length, source and bit), and its control-program snippets run against them.
// "string" without max_length is FixedString<64> (the default capacity); 128 and 255 as given.
use plc_core::{FixedString, GlobalMemory, IecType};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(description = "Test identifier")]
    pub info_test_id: FixedString<64>,
    #[plc(description = "Specimen name")]
    pub info_specimen_name: FixedString<128>,
    #[plc(description = "Operator notes")]
    pub info_notes: FixedString<255>,
    #[plc(link = "ethercat.impact67_0.digital_inputs")]
    pub impact67_0_digital_inputs: u16,
    #[plc(link = "ethercat.impact67_0.digital_outputs")]
    pub impact67_0_digital_outputs: u16,
    #[plc(source = "impact67_0_digital_inputs", bit = 0)]
    pub ls_centering_neg: bool,
    #[plc(source = "impact67_0_digital_inputs", bit = 1)]
    pub ls_centering_pos: bool,
    #[plc(source = "impact67_0_digital_inputs", bit = 2)]
    pub ls_lift_neg: bool,
    #[plc(source = "impact67_0_digital_outputs", bit = 0)]
    pub cr_lift_brake: bool,
}

/// The JSON variable-list format's usage snippets, with its log lines turned into what they observe.
fn process_tick(gm: &mut Gm, log: &mut Vec<String>) {
    // Read a string
    let test_id = gm.info_test_id.as_str();
    log.push(format!("Test: {}", test_id));
    // Write a string
    gm.info_test_id.set("TEST-001");
    // Check if empty
    if gm.info_notes.is_empty() {
        log.push("No notes entered".to_string());
    }
    // Read individual digital inputs
    if gm.ls_centering_neg {
        log.push("Centering negative limit reached".to_string());
    }
    // Set individual digital outputs
    gm.cr_lift_brake = true;
}

fn main() {
    let mut gm = Gm::default();
    let mut log = Vec::new();
    // One cycle as the framework runs it: unpack, tick, pack.
    gm.impact67_0_digital_inputs = 0b101; // neg and lift limit switches
    gm.impact67_0_digital_outputs = 0xF0F0; // unmapped output bits set
    gm.unpack_bits();
    assert!(gm.ls_centering_neg && !gm.ls_centering_pos && gm.ls_lift_neg);
    process_tick(&mut gm, &mut log);
    gm.pack_bits();
    assert_eq!(gm.impact67_0_digital_outputs, 0xF0F1, "unmapped bits are preserved");
    assert_eq!(
        log,
        ["Test: ", "No notes entered", "Centering negative limit reached"]
    );
    assert_eq!(gm.info_test_id, "TEST-001");

    // max_length is the capacity in bytes; longer text is silently truncated.
    let caps: Vec<usize> = Gm::VARIABLES[..3].iter().map(|v| v.size).collect();
    assert_eq!(caps, [64, 128, 255]);
    gm.info_notes.set(&"x".repeat(300));
    assert_eq!(gm.info_notes.len(), 255);

    let v = &Gm::VARIABLES[Gm::index_of("ls_lift_neg").unwrap()];
    assert_eq!(v.iec_type, IecType::Bool);
    let bit = v.bit.unwrap();
    assert_eq!((Gm::VARIABLES[bit.source].name, bit.bit), ("impact67_0_digital_inputs", 2));
    assert_eq!(Gm::VARIABLES[2].description, "Operator notes");
    assert_eq!(Gm::VARIABLES[3].link, Some("ethercat.impact67_0.digital_inputs"));
}
