use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW4")]
    channels: [i16; 4],
}

fn main() {}
