use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(linkk = "ethercat.io.inputs")]
    inputs: u16,
}

fn main() {}
