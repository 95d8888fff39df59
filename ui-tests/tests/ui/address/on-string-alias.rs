use plc_core::{FixedString, GlobalMemory};

type Label = FixedString<2>;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW4")]
    label: Label,
}

fn main() {}
