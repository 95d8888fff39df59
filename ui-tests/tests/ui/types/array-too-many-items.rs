use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    samples: [[f32; 256]; 257],
}

fn main() {}
