use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW4", direction = "output")]
    analog_in: i16,
}

fn main() {}
