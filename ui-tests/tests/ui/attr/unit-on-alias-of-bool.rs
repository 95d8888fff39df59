use plc_core::GlobalMemory;

// Through an alias only the compiler knows the type: the assertion says a unit is for numbers.
type Flag = bool;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(unit = "mm")]
    door_closed: Flag,
}

fn main() {}
