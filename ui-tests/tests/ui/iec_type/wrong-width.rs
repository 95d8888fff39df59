use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(iec_type = "WORD")]
    flags: u32,
    #[plc(iec_type = "DWORD")]
    speed: i32,
}

fn main() {}
