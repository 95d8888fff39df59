use plc_core::GlobalMemory;

type Channels = [u16; 2];

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW4")]
    channels: Channels,
}

fn main() {}
