// A bare integer literal is fine for REAL and LREAL: it has no declared type (IEC 61131-3), also
// through an alias and beyond the range of every integer type.
use plc_core::{GlobalMemory, Value};

type Lreal = f64;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = 42)]
    force: f32,
    #[plc(initial = -3)]
    offset: f64,
    #[plc(initial = 0)]
    zero: f32,
    #[plc(initial = 16777216)]
    aliased: Lreal,
    #[plc(initial = 100000000000000000000)]
    large: f64,
}

fn main() {
    let gm = Gm::default();
    assert_eq!(gm.force, 42.0);
    assert_eq!(gm.offset, -3.0);
    assert_eq!(gm.zero, 0.0);
    assert_eq!(gm.aliased, 16_777_216.0);
    assert_eq!(gm.large, 1e20);
    assert_eq!(gm.get(0, 0), Value::Real(42.0));
    assert_eq!(Gm::VARIABLES[1].initial, Some("-3"));
}
