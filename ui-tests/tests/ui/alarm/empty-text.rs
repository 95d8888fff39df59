use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm = "")]
    door: bool,
    #[plc(alarm(text = "   ", latched))]
    overtravel: bool,
    #[plc(alarm(severity = 700))]
    fault: bool,
}

fn main() {}
