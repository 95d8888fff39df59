use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    force: f32,
    #[plc(source = "force", bit = 0)]
    flag: bool,
}

fn main() {}
