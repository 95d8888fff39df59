// The generated code uses only fully qualified paths.
#![no_implicit_prelude]

#[derive(::plc_core::PlcStruct, Debug, Clone)]
pub struct Station {
    #[plc(alarm(text = "Door open", suppress_when = "off"))]
    door: bool,
    off: bool,
}

#[derive(::plc_core::GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(initial = 3, alarm(text = "Count", low = -1, high = 9, deadband = 0.5, delay = "1s"))]
    count: u16,
    #[plc(source = "count", bit = 1)]
    flag: bool,
    #[plc(at = "%QX0.0", alarm(text = "Lamp", latched, severity = 900, suppress_when = "flag"))]
    lamp: bool,
    label: ::plc_core::FixedString<4>,
    stations: [Station; 2],
}

fn main() {
    let gm = <Gm as ::std::default::Default>::default();
    ::std::assert!(gm.flag);
    ::std::assert_eq!(<Gm as ::plc_core::GlobalMemory>::ALARMS.len(), 4);
}
