use plc_core::{FixedString, GlobalMemory, Time};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm = "Bad batch id")]
    batch: FixedString<16>,
    #[plc(alarm(text = "Cycle too slow", high = 5.0))]
    cycle: Time,
}

fn main() {}
