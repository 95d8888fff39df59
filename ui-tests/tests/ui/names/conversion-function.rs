// The variable-editor rules: a variable cannot have the name of a standard function; the conversion functions
// of IEC 61131-3 ed. 3 come in several forms, each reserved.
use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    to_int: i16,
    real_trunc_int: i16,
    word_bcd_to_uint: u16,
    is_valid: bool,
}

fn main() {}
