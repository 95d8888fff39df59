use plc_core::GlobalMemory;

// A unit is for numbers: a bool is true or false, not a quantity.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(unit = "mm")]
    door_closed: bool,
}

fn main() {}
