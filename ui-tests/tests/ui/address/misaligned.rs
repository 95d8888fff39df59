use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW3")]
    a: i16,
    #[plc(at = "%ID6")]
    b: f32,
    #[plc(at = "%QL4")]
    c: u64,
}

fn main() {}
