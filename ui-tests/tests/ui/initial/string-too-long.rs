use plc_core::{FixedString, GlobalMemory};

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = "TEST-0001")]
    test_id: FixedString<8>,
}

fn main() {}
