use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm(u16, bool);

fn main() {}
