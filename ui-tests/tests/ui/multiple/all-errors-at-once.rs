use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(link = "ethercat.io")]
    inputs: u16,
    #[plc(source = "inputs", bit = 16)]
    a: bool,
    #[plc(at = "%IW3")]
    b: i16,
    #[plc(initial = 300)]
    c: u8,
    ton: bool,
    #[plc(colour = "red")]
    d: u8,
}

fn main() {}
