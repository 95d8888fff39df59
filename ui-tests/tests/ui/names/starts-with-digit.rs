use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(name = "1st_axis")]
    first_axis: i32,
}

fn main() {}
