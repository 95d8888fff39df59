use plc_core::GlobalMemory;

type Samples = [[u8; 4]; 0];

#[derive(GlobalMemory)]
pub struct Gm {
    samples: Samples,
}

fn main() {}
