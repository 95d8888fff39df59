// SINT never widens to an unsigned type: negative values have no unsigned equivalent.
use plc_core::convert::Widen;

fn main() {
    let _u: u32 = (-1i8).widen();
}
