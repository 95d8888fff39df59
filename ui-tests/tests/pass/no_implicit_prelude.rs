// The generated code uses only fully qualified paths.
#![no_implicit_prelude]

#[derive(::plc_core::GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(initial = 3)]
    count: u16,
    #[plc(source = "count", bit = 1)]
    flag: bool,
    #[plc(at = "%QX0.0")]
    lamp: bool,
    label: ::plc_core::FixedString<4>,
}

fn main() {
    let gm = <Gm as ::std::default::Default>::default();
    ::std::assert!(gm.flag);
}
