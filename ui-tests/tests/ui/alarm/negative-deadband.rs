use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm(text = "Oil temperature", high = 80.0, deadband = -1.5))]
    oil: f32,
}

fn main() {}
