use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
#[plc(byte_order = "little", byte_order = "big")]
pub struct Gm {
    #[plc(at = "%IW4")]
    speed: i16,
}

fn main() {}
