use plc_core::{FixedString, GlobalMemory, Time};

type Delay = Time;
type Label = FixedString<8>;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = "T#1h75m")]
    bad_literal: Delay,
    #[plc(initial = 500)]
    bare_number: Delay,
    #[plc(initial = "T#5s")]
    fine: Delay,
    #[plc(initial = "T#5s")]
    text_that_looks_like_a_duration: Label,
}

fn main() {}
