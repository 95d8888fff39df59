use plc_core::GlobalMemory;

// A unit is the unit's symbol: an empty one says nothing.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(unit = "")]
    force: f32,
}

fn main() {}
