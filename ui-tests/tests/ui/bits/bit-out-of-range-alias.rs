use plc_core::GlobalMemory;

type Word = u16;

#[derive(GlobalMemory)]
pub struct Gm {
    w: Word,
    #[plc(source = "w", bit = 16)]
    flag: bool,
}

fn main() {}
