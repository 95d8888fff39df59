use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW4")]
    analog_in: i16,
    #[plc(at = "%IB5")]
    status: u8,
    #[plc(at = "%IX4.3")]
    ready: bool,
}

fn main() {}
