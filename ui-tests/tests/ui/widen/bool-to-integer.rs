// BOOL has boolean semantics, not a numeric bit container (IEC 61131-3). Named through the trait,
// so the compiler reports the missing widening rather than a plain type mismatch.
use plc_core::convert::Widen;

fn main() {
    let _i: u8 = <bool as Widen<u8>>::widen(true);
}
