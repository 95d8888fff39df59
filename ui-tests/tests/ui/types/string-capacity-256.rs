use plc_core::{FixedString, GlobalMemory};

#[derive(GlobalMemory)]
pub struct Gm {
    note: FixedString<256>,
}

fn main() {}
