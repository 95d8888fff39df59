use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm(text = "Oil temperature", low = 90.0, high = 80.0))]
    oil: f32,
    #[plc(alarm(text = "Pressure", high = 8.0, high_high = 6.5))]
    pressure: f64,
    #[plc(alarm(text = "Level", low_low = 5, low = -5, high = 50))]
    level: i16,
    #[plc(alarm(text = "Speed", low = 100, high = 100))]
    speed: u16,
}

fn main() {}
