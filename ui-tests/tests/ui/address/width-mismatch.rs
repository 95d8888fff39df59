use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW4")]
    force: f32,
    #[plc(at = "%QB0")]
    horn: bool,
    #[plc(at = "%IX2.0")]
    level: u8,
}

fn main() {}
