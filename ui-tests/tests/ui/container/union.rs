use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub union Gm {
    a: u32,
    b: f32,
}

fn main() {}
