use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm;

fn main() {}
