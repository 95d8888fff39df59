// Arrays of up to 3 dimensions and 65,535 items (the variable-editor rules), also of strings.
use plc_core::{FixedString, GlobalMemory};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    cube: [[[u8; 2]; 3]; 4],
    largest: [u8; 65535],
    labels: [FixedString<16>; 4],
    flags: [bool; 8],
}

fn main() {
    assert_eq!(Gm::VARIABLES[0].dims, &[4, 3, 2]);
    assert_eq!(Gm::VARIABLES[1].size, 65535);
    assert_eq!(Gm::VARIABLES[2].size, 64);
}
