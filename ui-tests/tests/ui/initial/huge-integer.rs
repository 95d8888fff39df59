use plc_core::GlobalMemory;

type Level = f32;

#[derive(GlobalMemory)]
pub struct Gm {
    // Beyond i128 and beyond f32: out of range for REAL, as for any integer.
    #[plc(initial = 1000000000000000000000000000000000000000000)]
    force: f32,
    #[plc(initial = 1000000000000000000000000000000000000000000)]
    aliased: Level,
    #[plc(initial = 100000000000000000000)]
    count: u64,
}

fn main() {}
