use plc_core::GlobalMemory;

// `deadband` is a number, not a string.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(deadband = "0.5")]
    force: f32,
}

fn main() {}
