use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    w: u16,
    #[plc(source = "w", bit = 1.5)]
    flag: bool,
    #[plc(description = 5)]
    speed: i32,
}

fn main() {}
