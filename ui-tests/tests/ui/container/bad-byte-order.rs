use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
#[plc(byte_order = "middle")]
pub struct Gm {
    #[plc(at = "%IW0")]
    speed: i16,
}

fn main() {}
