use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm(text = "Specimen not centred", delay = "two seconds"))]
    centred: bool,
    #[plc(alarm(text = "Guard door open", delay = "-1s"))]
    door: bool,
    #[plc(alarm(text = "Overtravel", delay = "T#1h75m"))]
    overtravel: bool,
    #[plc(alarm(text = "Drive fault", delay = 2))]
    fault: bool,
}

fn main() {}
