use plc_core::GlobalMemory;

// `ux` is a flag: the variable is meant for an operator UI.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(ux = 3)]
    start: bool,
}

fn main() {}
