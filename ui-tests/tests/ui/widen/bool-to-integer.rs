// BOOL has boolean semantics, not a numeric bit container (seed 001).
use plc_core::convert::Widen;

fn main() {
    let _i: u8 = true.widen();
}
