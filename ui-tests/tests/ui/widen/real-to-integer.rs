// Real to integer is never implicit: it would truncate (seed 001, use `real_to_dint`).
use plc_core::convert::Widen;

fn main() {
    let _i: i64 = 1.5f32.widen();
}
