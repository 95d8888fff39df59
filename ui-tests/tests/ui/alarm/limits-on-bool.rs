use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm(text = "Guard door open", high = 1.0, deadband = 0.5))]
    door: bool,
}

fn main() {}
