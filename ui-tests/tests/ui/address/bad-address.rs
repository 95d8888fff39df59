use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IX3.8")]
    a: bool,
    #[plc(at = "IW4")]
    b: i16,
    #[plc(at = "%IS4")]
    c: u8,
    #[plc(at = "%IW4.1")]
    d: i16,
}

fn main() {}
