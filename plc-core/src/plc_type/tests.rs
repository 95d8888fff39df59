//! Tests of the `PlcType` impls: array dimensions and row-major elements, the stored forms,
//! element errors and bit sources.

use super::{BitSource, ElementError, PlcType};
use crate::{FixedString, IecType, Time, Value};
use zerocopy::IntoBytes;

#[test]
fn arrays_report_dims_and_elements() {
    type A = [[[u8; 2]; 3]; 4];
    assert_eq!(A::DIMS, &[4, 3, 2]);
    assert_eq!((A::RANK, A::ELEMENTS), (3, 24));
    assert_eq!(<u8 as PlcType>::DIMS, &[] as &[usize]);
    assert_eq!(<[FixedString<8>; 2]>::STRING_CAPACITY, 8);
}

#[test]
fn row_major_elements() {
    let mut a = [[0u16; 3]; 2];
    a.set_element(4, Value::UInt(9), IecType::Uint).unwrap();
    assert_eq!(a[1][1], 9);
    assert_eq!(a.get_element(4), Some(Value::UInt(9)));
    assert_eq!(a.get_element(6), None);
    assert_eq!(
        a.set_element(6, Value::UInt(1), IecType::Uint),
        Err(ElementError::OutOfRange { len: 6 })
    );
    assert!(matches!(
        a.set_element(0, Value::Int(-1), IecType::Uint),
        Err(ElementError::Value(_))
    ));
    assert_eq!(a[0][0], 0);
}

#[test]
fn repr_is_little_endian_and_unaligned() {
    let r = 0x1234u16.to_repr();
    assert_eq!(r.as_bytes(), &[0x34, 0x12]);
    assert_eq!(core::mem::align_of::<<[f64; 3] as PlcType>::Repr>(), 1);
    assert!(bool::from_repr(&7));
    assert_eq!(f64::from_repr(&(-2.5f64).to_repr()), -2.5);
}

#[test]
fn element_errors_explain_themselves() {
    let out = ElementError::OutOfRange { len: 6 };
    assert_eq!(
        out.to_string(),
        "element out of range: the variable has 6 elements (0..6)"
    );
    let value = [0u8; 1]
        .set_element(0, Value::Int(-1), IecType::Usint)
        .unwrap_err();
    assert_eq!(value.to_string(), "out of range for USINT (0..=255)");
    #[cfg(feature = "std")]
    {
        let boxed: Box<dyn std::error::Error> = Box::new(value);
        assert_eq!(boxed.to_string(), "out of range for USINT (0..=255)");
    }
}

#[test]
fn a_time_is_its_nanoseconds_in_little_endian() {
    let t = Time::from_nanos(-2);
    assert_eq!(t.to_repr().as_bytes(), &(-2i64).to_le_bytes());
    assert_eq!(Time::from_repr(&t.to_repr()), t);
    let mut times = [Time::ZERO; 2];
    times
        .set_element(1, Value::Time(Time::from_secs(5)), IecType::Ltime)
        .unwrap();
    assert_eq!(times.get_element(1), Some(Value::Time(Time::from_secs(5))));
    assert!(times.set_element(0, Value::Int(5), IecType::Ltime).is_err());
    assert_eq!(<Time as PlcType>::IEC_TYPE, IecType::Ltime);
}

#[test]
fn bit_source_keeps_other_bits() {
    assert_eq!(0b1010u8.with_bit(0, true), 0b1011);
    assert_eq!(0b1010u8.with_bit(1, false), 0b1000);
    assert!((-1i16).bit(15));
    assert_eq!(0i64.with_bit(63, true), i64::MIN);
}
