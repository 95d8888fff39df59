// The example variables of the JSON variable-list format (impact67 IO with bit-mapped limit switches and a
// lift brake, a test id, a nonvolatile offset) plus a located input, a bit-string word and a
// 2-D array.
use plc_core::{FixedString, GlobalMemory};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    /// Digital inputs of the IO module
    #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "input")]
    pub impact67_0_digital_inputs: u16,
    #[plc(source = "impact67_0_digital_inputs", bit = 0)]
    pub ls_centering_neg: bool,
    #[plc(link = "ethercat.impact67_0.digital_outputs", direction = "output")]
    pub impact67_0_digital_outputs: u16,
    #[plc(source = "impact67_0_digital_outputs", bit = 0)]
    pub cr_lift_brake: bool,
    #[plc(initial = "TEST-001", description = "Test identifier")]
    pub info_test_id: FixedString<64>,
    #[plc(nonvolatile, initial = 12.5)]
    pub press_home_offset_mm: f64,
    #[plc(at = "%IW4")]
    pub analog_in: i16,
    #[plc(iec_type = "WORD")]
    pub mode_word: u16,
    pub recipe_speeds: [[f32; 4]; 3],
}

fn main() {
    let gm = Gm::default();
    assert_eq!(gm.info_test_id, "TEST-001");
    assert_eq!(Gm::VARIABLES.len(), 9);
}
