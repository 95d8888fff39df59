use plc_core::{FixedString, GlobalMemory, IecType, Time};

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Gm {
    a: bool,
    b: i8,
    c: i16,
    d: i32,
    e: i64,
    f: u8,
    g: u16,
    h: u32,
    i: u64,
    j: f32,
    k: f64,
    #[plc(iec_type = "BYTE")]
    l: u8,
    #[plc(iec_type = "WORD")]
    m: u16,
    #[plc(iec_type = "DWORD")]
    n: u32,
    #[plc(iec_type = "LWORD")]
    o: u64,
    p: FixedString<1>,
    q: FixedString<255>,
    dwell: Time,
}

fn main() {
    let types: Vec<IecType> = Gm::VARIABLES.iter().map(|v| v.iec_type).collect();
    assert_eq!(types[..16], IecType::ALL[..16]);
    assert_eq!(types[16], IecType::String);
    assert_eq!(types[17], IecType::ALL[16]);
}
