use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm)]
    a: bool,
    #[plc(alarm(text = "Door", latch))]
    b: bool,
    #[plc(alarm(text = "Door", latched = true, high = "80"))]
    c: bool,
    #[plc(alarm(text = "Door", text = "Again"))]
    d: bool,
    #[plc(alarm_when = false)]
    e: bool,
    #[plc(alarm(text = "Door", alarm_when = false), alarm_when = false)]
    f: bool,
    #[plc(alarm = 5)]
    g: bool,
}

fn main() {}
