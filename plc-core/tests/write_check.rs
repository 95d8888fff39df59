//! The one write check: what a tool may write, decided the same way against the program's
//! own tables here as against a segment's descriptor in a tool.

use plc_core::write::{Refusal, Write, check};
use plc_core::{FixedString, GlobalMemory, PlcStruct, Value, ValueError};

#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
struct Axis {
    target: f64,
    #[plc(read_only)]
    actual: f64,
}

#[derive(GlobalMemory, Debug, Clone)]
struct Gm {
    #[plc(direction = "command")]
    speed: f32,
    #[plc(direction = "command")]
    recipe: [u8; 3],
    axes: [Axis; 2],
    #[plc(read_only)]
    serial: u32,
    #[plc(direction = "status")]
    state: u16,
    label: FixedString<4>,
    grid: [[Axis; 2]; 3],
}

fn w(index: usize, leaf: usize, value: Value) -> Write {
    Write { index, leaf, value }
}

fn refused(write: Write) -> String {
    check(Gm::VARIABLES, write)
        .map(|ok| panic!("accepted: {ok:?}"))
        .unwrap_err()
        .to_string()
}

#[test]
fn accepted_writes_come_back_fitted_to_their_type() {
    let ok = check(Gm::VARIABLES, w(0, 0, Value::UInt(3))).unwrap();
    assert_eq!(*ok.write(), w(0, 0, Value::Real(3.0)));
    let ok = check(Gm::VARIABLES, w(1, 2, Value::Int(200))).unwrap();
    assert_eq!(ok.write().value, Value::UInt(200));
    // A structure's writable member, by its leaf: axes[1].target is leaf 2.
    let ok = check(Gm::VARIABLES, w(2, 2, Value::Real(1.5))).unwrap();
    assert_eq!(ok.write().leaf, 2);
}

#[test]
fn each_refusal_names_the_variable_and_the_reason() {
    assert_eq!(
        refused(w(9, 0, Value::Int(1))),
        "there is no variable number 9: the program has 7"
    );
    assert_eq!(
        refused(w(3, 0, Value::Int(1))),
        "`serial` cannot be written: it is read-only"
    );
    assert_eq!(
        refused(w(4, 0, Value::Int(1))),
        "`state` cannot be written: it is a status variable: the program reports it"
    );
    assert_eq!(
        refused(w(1, 3, Value::Int(1))),
        "`recipe` has 3 elements: element 3 is out of range 0..3"
    );
    // Beyond an array of structures: the variable, not its first value (`axes[0].target`).
    assert_eq!(
        refused(w(2, 9999, Value::Real(1.0))),
        "`axes` has 4 elements: element 9999 is out of range 0..4"
    );
    assert_eq!(
        refused(w(2, 1, Value::Real(1.0))),
        "`axes[0].actual` cannot be written: it is read-only"
    );
    assert_eq!(
        refused(w(2, 3, Value::Real(1.0))),
        "`axes[1].actual` cannot be written: it is read-only"
    );
    // grid[2,1] is element 5 of the 3x2 array: its `actual` is leaf 5 * 2 + 1.
    assert_eq!(
        refused(w(6, 11, Value::Real(1.0))),
        "`grid[2,1].actual` cannot be written: it is read-only"
    );
    assert_eq!(
        refused(w(1, 0, Value::Int(256))),
        "`recipe`: out of range for USINT (0..=255)"
    );
    assert_eq!(
        refused(w(
            5,
            0,
            Value::Text(FixedString::from_str_truncate("hello"))
        )),
        "`label`: text of 5 bytes is longer than the capacity of 4 bytes"
    );
}

#[test]
fn nan_and_infinities_are_refused_for_real_and_lreal_alike() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let err = check(Gm::VARIABLES, w(0, 0, Value::Real(bad))).unwrap_err();
        assert!(
            matches!(
                err,
                Refusal::Value {
                    error: ValueError::NotFinite { .. },
                    ..
                }
            ),
            "{err}"
        );
        assert_eq!(
            refused(w(2, 0, Value::Real(bad))),
            "`axes[0].target`: not a finite number: LREAL takes no NaN or infinity from a tool"
        );
    }
    // The largest finite numbers are numbers.
    assert!(check(Gm::VARIABLES, w(2, 0, Value::Real(f64::MAX))).is_ok());
    assert!(check(Gm::VARIABLES, w(0, 0, Value::Real(f32::MAX as f64))).is_ok());
}
