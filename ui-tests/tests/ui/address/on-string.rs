use plc_core::{FixedString, GlobalMemory};

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IB4")]
    label: FixedString<8>,
}

fn main() {}
