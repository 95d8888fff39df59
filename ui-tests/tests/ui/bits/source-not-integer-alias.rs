use plc_core::GlobalMemory;

type Force = f32;

#[derive(GlobalMemory)]
pub struct Gm {
    force: Force,
    #[plc(source = "force", bit = 0)]
    flag: bool,
}

fn main() {}
