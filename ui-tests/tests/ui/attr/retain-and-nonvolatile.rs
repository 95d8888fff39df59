use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    // `retain` is an alias of `nonvolatile`: one of them is enough.
    #[plc(nonvolatile, retain)]
    offset: f64,
}

fn main() {}
