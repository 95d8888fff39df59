use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    speed: i32,
    #[plc(name = "SPEED")]
    speed_setpoint: i32,
}

fn main() {}
