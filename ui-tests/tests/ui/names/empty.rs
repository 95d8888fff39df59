use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(name = "")]
    speed: i32,
}

fn main() {}
