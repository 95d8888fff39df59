use plc_core::{FixedString, GlobalMemory};

type Note = FixedString<300>;

#[derive(GlobalMemory)]
pub struct Gm {
    note: Note,
}

fn main() {}
