use plc_core::GlobalMemory;

type Flags = u32;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(iec_type = "WORD")]
    flags: Flags,
}

fn main() {}
