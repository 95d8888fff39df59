use plc_core::{FixedString, GlobalMemory};

type Code = FixedString<4>;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = "TEST-001")]
    code: Code,
}

fn main() {}
