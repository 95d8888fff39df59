use plc_core::GlobalMemory;

type Samples = [u8; 70000];

#[derive(GlobalMemory)]
pub struct Gm {
    samples: Samples,
}

fn main() {}
