use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    w: u16,
    #[plc(source = "w", bit = 2)]
    door_closed: bool,
    #[plc(source = "w", bit = 2)]
    guard_closed: bool,
}

fn main() {}
