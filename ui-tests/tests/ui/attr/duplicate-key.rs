use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(description = "first", description = "second")]
    speed: i32,
}

fn main() {}
