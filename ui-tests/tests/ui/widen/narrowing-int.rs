// Narrowing (DINT to INT) needs an explicit conversion such as `dint_to_int` (IEC 61131-3).
use plc_core::convert::Widen;

fn main() {
    let _small: i16 = 100_000i32.widen();
}
