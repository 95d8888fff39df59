use plc_core::GlobalMemory;

// The reporting deadband is 0 or more: how far the value must move before a change is published.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(unit = "kN", deadband = -0.5)]
    force: f32,
}

fn main() {}
