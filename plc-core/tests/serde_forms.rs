//! The serde forms of plc-core's types, read back from owned JSON values as tools hold them
//! (`serde_json::from_value` hands out owned strings, never borrowed ones).
#![cfg(feature = "serde")]

use plc_core::{Access, Direction, FixedString, IecType};
use serde_json::{Value, json};

#[test]
fn iec_type_reads_from_owned_and_escaped_strings() {
    assert_eq!(
        serde_json::from_value::<IecType>(json!("dint")).unwrap(),
        IecType::Dint
    );
    assert_eq!(
        serde_json::from_value::<IecType>(Value::String("u16".to_owned())).unwrap(),
        IecType::Uint
    );
    // An escape forces serde_json to build the string: no borrow of the input exists.
    assert_eq!(
        serde_json::from_str::<IecType>(r#""DI\u004eT""#).unwrap(),
        IecType::Dint
    );
    let e = serde_json::from_value::<IecType>(json!("INTEGER")).unwrap_err();
    assert!(e.to_string().contains("\"INTEGER\""), "{e}");
    assert_eq!(
        serde_json::to_value(IecType::Lreal).unwrap(),
        json!("LREAL")
    );
}

#[test]
fn other_types_read_from_owned_values_too() {
    let s: FixedString<8> = serde_json::from_value(json!("TEST-001")).unwrap();
    assert_eq!(s, "TEST-001");
    assert!(serde_json::from_value::<FixedString<2>>(json!("abc")).is_err());
    assert_eq!(
        serde_json::from_value::<Access>(json!("read_only")).unwrap(),
        Access::ReadOnly
    );
    assert_eq!(
        serde_json::from_value::<Direction>(json!("input")).unwrap(),
        Direction::Input
    );
}

#[test]
fn a_time_is_its_literal() {
    use plc_core::Time;
    assert_eq!(
        serde_json::to_value(Time::from_millis(1500)).unwrap(),
        json!("LTIME#1s500ms")
    );
    assert_eq!(
        serde_json::from_value::<Time>(json!("T#2h_30m")).unwrap(),
        Time::from_secs(9000)
    );
    let e = serde_json::from_value::<Time>(json!("T#1h75m")).unwrap_err();
    assert!(e.to_string().contains("below 60m"), "{e}");
    assert!(serde_json::from_value::<Time>(json!(1500)).is_err());
}
