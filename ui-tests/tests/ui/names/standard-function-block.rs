use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    ton: bool,
    r_trig: bool,
    abs: f32,
}

fn main() {}
