// DINT does not widen to REAL: a 32-bit integer does not fit the 24-bit mantissa (IEC 61131-3).
use plc_core::convert::Widen;

fn main() {
    let _r: f32 = 100_000i32.widen();
}
