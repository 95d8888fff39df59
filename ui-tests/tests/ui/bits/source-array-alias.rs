use plc_core::GlobalMemory;

type Words = [u16; 2];

// One mistake, one error: the source is not an integer, so bit 16 is not judged as well.
#[derive(GlobalMemory)]
pub struct Gm {
    words: Words,
    #[plc(source = "words", bit = 16)]
    flag: bool,
}

fn main() {}
