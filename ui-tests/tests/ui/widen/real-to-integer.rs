// Real to integer is never implicit: it would truncate (IEC 61131-3, use `real_to_dint`).
use plc_core::convert::Widen;

fn main() {
    let _i: i64 = 1.5f32.widen();
}
