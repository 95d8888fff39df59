// An unsigned type widens to a signed one only of strictly greater width (UINT to DINT, not INT).
use plc_core::convert::Widen;

fn main() {
    let _i: i16 = 40_000u16.widen();
}
