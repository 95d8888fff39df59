use plc_core::GlobalMemory;

// `quantity` names the physical quantity as a string, such as "force".
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(quantity = 1)]
    force: f64,
}

fn main() {}
