use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(iec_type = "TIME")]
    elapsed: u32,
}

fn main() {}
