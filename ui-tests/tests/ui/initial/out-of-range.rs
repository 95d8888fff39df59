use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = 256)]
    level: u8,
    #[plc(initial = -1)]
    count: u32,
    #[plc(initial = 1e39)]
    force: f32,
}

fn main() {}
