use plc_core::GlobalMemory;

const SPEED: i32 = 5;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = SPEED)]
    speed: i32,
}

fn main() {}
