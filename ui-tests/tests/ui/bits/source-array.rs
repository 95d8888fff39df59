use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    words: [u16; 2],
    #[plc(source = "words", bit = 0)]
    flag: bool,
}

fn main() {}
