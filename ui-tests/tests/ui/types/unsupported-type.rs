use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    name: String,
    count: usize,
    samples: Vec<f32>,
    letter: char,
    pair: (u8, u8),
}

fn main() {}
