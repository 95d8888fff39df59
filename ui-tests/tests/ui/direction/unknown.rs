use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(direction = "in")]
    speed: i32,
}

fn main() {}
