use plc_core::GlobalMemory;

type Force = f32;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(at = "%IW4")]
    force: Force,
}

fn main() {}
