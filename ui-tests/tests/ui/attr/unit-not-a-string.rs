use plc_core::GlobalMemory;

// `unit` is the unit's symbol as a string, such as "mm".
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(unit = mm)]
    position: f64,
}

fn main() {}
