use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(name = "motor-speed")]
    motor_speed: i32,
}

fn main() {}
