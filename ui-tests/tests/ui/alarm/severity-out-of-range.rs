use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm(text = "Guard door open", severity = 0))]
    door: bool,
    #[plc(alarm(text = "Overtravel", severity = 1001))]
    overtravel: bool,
    #[plc(alarm(text = "Drive fault", severity = -5))]
    fault: bool,
    #[plc(alarm(text = "Force", severity = "high"))]
    force: bool,
}

fn main() {}
