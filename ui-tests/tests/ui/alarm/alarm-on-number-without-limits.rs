use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm = "Force above rating")]
    force: f64,
    #[plc(alarm(text = "Speed", high = 3000, alarm_when = false))]
    speed: i32,
}

fn main() {}
