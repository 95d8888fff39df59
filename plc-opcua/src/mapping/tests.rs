use super::*;
use plc_core::{Access, Direction};

fn var(
    name: &str,
    ty: IecType,
    dims: &[usize],
    access: Access,
    direction: Direction,
) -> VarDescriptor {
    let element = if ty == IecType::String {
        16
    } else {
        (ty.bits() as usize).div_ceil(8).max(1)
    };
    VarDescriptor {
        rust_type: String::new(),
        dims: dims.to_vec(),
        access,
        direction,
        ..VarDescriptor::basic(name, ty, 0, element * dims.iter().product::<usize>())
    }
}

fn scalar(ty: IecType) -> VarDescriptor {
    var("v", ty, &[], Access::ReadWrite, Direction::Internal)
}

#[test]
fn every_iec_type_has_its_opc_ua_data_type() {
    use IecType::*;
    let table = [
        (Bool, DataTypeId::Boolean),
        (Sint, DataTypeId::SByte),
        (Usint, DataTypeId::Byte),
        (Byte, DataTypeId::Byte),
        (Int, DataTypeId::Int16),
        (Uint, DataTypeId::UInt16),
        (Word, DataTypeId::UInt16),
        (Dint, DataTypeId::Int32),
        (Udint, DataTypeId::UInt32),
        (Dword, DataTypeId::UInt32),
        (Lint, DataTypeId::Int64),
        (Ulint, DataTypeId::UInt64),
        (Lword, DataTypeId::UInt64),
        (Real, DataTypeId::Float),
        (Lreal, DataTypeId::Double),
        (String, DataTypeId::String),
    ];
    for (ty, id) in table {
        assert_eq!(data_type(ty), id, "{ty}");
    }
}

#[test]
fn values_become_variants_of_the_variables_own_type() {
    assert_eq!(
        to_variant(IecType::Sint, Value::Int(-5)),
        Variant::SByte(-5)
    );
    assert_eq!(
        to_variant(IecType::Word, Value::UInt(0xBEEF)),
        Variant::UInt16(0xBEEF)
    );
    assert_eq!(
        to_variant(IecType::Real, Value::Real(1.5)),
        Variant::Float(1.5)
    );
    assert_eq!(
        to_variant(IecType::Lreal, Value::Real(1.5)),
        Variant::Double(1.5)
    );
    assert_eq!(
        to_variant(IecType::Bool, Value::Bool(true)),
        Variant::Boolean(true)
    );
    let mut text = FixedString::<255>::new();
    text.set("TEST-1");
    assert_eq!(
        to_variant(IecType::String, Value::Text(text)),
        Variant::from("TEST-1")
    );
    // A kind the type cannot hold (a damaged descriptor) is no value, not a wrong one.
    assert_eq!(to_variant(IecType::Int, Value::Real(1.0)), Variant::Empty);
}

#[test]
fn arrays_are_one_value_with_their_dimensions() {
    let grid = var(
        "grid",
        IecType::Int,
        &[2, 3],
        Access::ReadWrite,
        Direction::Internal,
    );
    assert_eq!(value_rank(&grid), (2, Some(vec![2, 3])));
    assert_eq!(value_rank(&scalar(IecType::Int)), (-1, None));
    let elements: Vec<Value> = (0..6).map(Value::Int).collect();
    let Variant::Array(array) = to_value_variant(&grid, elements.clone()) else {
        panic!("an array variant");
    };
    assert_eq!(array.dimensions, Some(vec![2, 3]));
    assert_eq!(array.values[5], Variant::Int16(5));
    // Written back whole, the same elements; other dimensions or lengths are refused.
    let written = written_elements(&grid, &Variant::Array(array.clone())).unwrap();
    assert_eq!(written, elements);
    let flat = Array::new(VariantScalarTypeId::Int16, array.values.clone()).unwrap();
    assert_eq!(
        written_elements(&grid, &Variant::from(flat)),
        Err(StatusCode::BadTypeMismatch)
    );
    let short = Array::new(VariantScalarTypeId::Int16, vec![Variant::Int16(1)]).unwrap();
    let row = var(
        "row",
        IecType::Int,
        &[3],
        Access::ReadWrite,
        Direction::Internal,
    );
    assert_eq!(
        written_elements(&row, &Variant::from(short)),
        Err(StatusCode::BadTypeMismatch)
    );
    assert_eq!(
        written_elements(&scalar(IecType::Int), &Variant::from(array)),
        Err(StatusCode::BadTypeMismatch)
    );
}

#[test]
fn access_level_says_where_a_tool_may_write_and_anonymous_sessions_never_do() {
    let rw = AccessLevel::CURRENT_READ | AccessLevel::CURRENT_WRITE;
    let cases = [
        (Access::ReadWrite, Direction::Command, rw),
        (Access::ReadWrite, Direction::Internal, rw),
        (Access::ReadWrite, Direction::Output, rw),
        (
            Access::ReadWrite,
            Direction::Input,
            AccessLevel::CURRENT_READ,
        ),
        (
            Access::ReadWrite,
            Direction::Status,
            AccessLevel::CURRENT_READ,
        ),
        (
            Access::ReadOnly,
            Direction::Command,
            AccessLevel::CURRENT_READ,
        ),
    ];
    for (access, direction, level) in cases {
        let v = var("v", IecType::Int, &[], access, direction);
        assert_eq!(
            access_level(&v).bits(),
            level.bits(),
            "{access:?} {direction:?}"
        );
        assert_eq!(user_access_level(level, false).bits(), level.bits());
        assert_eq!(
            user_access_level(level, true).bits(),
            AccessLevel::CURRENT_READ.bits()
        );
    }
}

#[test]
fn node_ids_are_the_paths_plc_get_takes_in_the_segments_namespace() {
    assert_eq!(namespace_uri("press_1"), "urn:plc-vars:press_1");
    assert_eq!(
        variable_node_id(3, "Force_kN").to_string(),
        "ns=3;s=Force_kN"
    );
    // The program object is numeric: no variable's path can take its NodeId.
    assert_eq!(NodeId::new(3, PROGRAM_OBJECT_ID).to_string(), "ns=3;i=1");
}

#[test]
fn written_variants_become_values_and_other_kinds_are_refused() {
    assert_eq!(from_variant(&Variant::Int32(-7)), Ok(Value::Int(-7)));
    assert_eq!(from_variant(&Variant::UInt64(7)), Ok(Value::UInt(7)));
    assert_eq!(from_variant(&Variant::Float(0.5)), Ok(Value::Real(0.5)));
    // NaN and the infinities reach the one write check, which refuses them for every tool.
    for v in [Variant::Double(f64::NAN), Variant::Float(f32::INFINITY)] {
        assert!(
            matches!(from_variant(&v), Ok(Value::Real(r)) if !r.is_finite()),
            "{v:?}"
        );
    }
    let not_finite = ShmError::Value {
        variable: "speed".into(),
        error: plc_core::ValueError::NotFinite {
            expected: plc_core::IecType::Real,
        },
    };
    assert_eq!(write_refusal(&not_finite), StatusCode::BadOutOfRange);
    assert_eq!(
        from_variant(&Variant::from("x".repeat(256))),
        Err(StatusCode::BadOutOfRange)
    );
    assert_eq!(
        from_variant(&Variant::DateTime(Box::default())),
        Err(StatusCode::BadTypeMismatch)
    );
}

#[test]
fn refusals_map_to_the_status_codes_of_the_standard() {
    let not_writable = ShmError::NotWritable {
        variable: "x".into(),
        reason: "it is an input",
    };
    assert_eq!(write_refusal(&not_writable), StatusCode::BadNotWritable);
    let value = |error| ShmError::Value {
        variable: "x".into(),
        error,
    };
    let range = value(ValueError::OutOfRange {
        expected: IecType::Uint,
    });
    assert_eq!(write_refusal(&range), StatusCode::BadOutOfRange);
    let long = value(ValueError::TooLong {
        len: 70,
        capacity: 64,
    });
    assert_eq!(write_refusal(&long), StatusCode::BadOutOfRange);
    let kind = value(ValueError::WrongKind {
        expected: IecType::Real,
        found: "text",
    });
    assert_eq!(write_refusal(&kind), StatusCode::BadTypeMismatch);
    assert_eq!(
        write_refusal(&ShmError::OwnerGone("s".into())),
        StatusCode::BadNoCommunication
    );
    assert_eq!(
        write_refusal(&ShmError::QueueFull("s".into())),
        StatusCode::BadTooManyOperations
    );
    let too_many = ShmError::RequestCount {
        name: "s".into(),
        what: "writes",
        count: 2000,
        most: 1024,
    };
    assert_eq!(write_refusal(&too_many), StatusCode::BadTooManyOperations);
}

#[test]
fn a_write_to_a_forced_value_is_refused_as_locked() {
    let forced = ShmError::Forced {
        name: "s".into(),
        variable: "speed".into(),
        reason: "`speed` is forced (by uid 1000 since 2026-12-03 21:35:52 UTC): release it first"
            .into(),
    };
    assert_eq!(write_refusal(&forced), StatusCode::BadLocked);
    // A program's own refusal is another thing: not a lock.
    let rejected = ShmError::WriteRejected {
        name: "s".into(),
        variable: "speed".into(),
        reason: "too fast".into(),
    };
    assert_ne!(write_refusal(&rejected), StatusCode::BadLocked);
}

#[test]
fn a_forced_value_reads_as_overridden_while_its_owner_runs() {
    assert_eq!(
        forced_status(StatusCode::Good, true),
        StatusCode::GoodLocalOverride
    );
    assert_eq!(forced_status(StatusCode::Good, false), StatusCode::Good);
    // The owner's state says more: its values are stale or gone, forced or not.
    for status in [
        StatusCode::UncertainLastUsableValue,
        StatusCode::BadNoCommunication,
    ] {
        assert_eq!(forced_status(status, true), status);
    }
}

#[test]
fn a_node_holds_a_force_when_one_of_its_own_values_is_forced() {
    // Variable 2's leaf 7 (an element of an array, or a member's), variable 4's leaf 0.
    let forced = [(2, 7), (4, 0)];
    assert!(holds_force(&forced, 2, 0, 10), "the whole array");
    assert!(holds_force(&forced, 2, 7, 1), "the one element's member");
    assert!(
        holds_force(&forced, 2, 5, 3),
        "a member array from leaf 5 to 7"
    );
    assert!(!holds_force(&forced, 2, 0, 7), "leaves 0 to 6 only");
    assert!(!holds_force(&forced, 2, 8, 4), "the leaves after it");
    assert!(!holds_force(&forced, 3, 0, 100), "another variable");
    assert!(holds_force(&forced, 4, 0, 1));
    assert!(!holds_force(&[], 4, 0, 1));
}

#[test]
fn the_owners_state_decides_the_status_of_its_values() {
    assert_eq!(value_status(OwnerState::Running), StatusCode::Good);
    assert_eq!(
        value_status(OwnerState::Stalled),
        StatusCode::UncertainLastUsableValue
    );
    for gone in [OwnerState::Gone, OwnerState::Stopped, OwnerState::Faulted] {
        assert_eq!(value_status(gone), StatusCode::BadNoCommunication, "{gone}");
    }
}

#[test]
fn the_cycle_stamp_becomes_the_opc_ua_source_time() {
    assert_eq!(source_time(0), None, "no cycle yet");
    // 2024-01-01T00:00:00.5Z
    let t = source_time(1_704_067_200_500_000_000).unwrap();
    assert_eq!(t.to_rfc3339(), "2024-01-01T00:00:00.500Z");
}

#[test]
fn durations_are_milliseconds_both_ways() {
    use opcua::types::DataTypeId;
    let d = scalar(IecType::Ltime);
    assert_eq!(data_type(IecType::Ltime), DataTypeId::Duration);
    assert_eq!(
        to_variant(
            IecType::Ltime,
            Value::Time(plc_core::Time::from_millis(1500))
        ),
        Variant::Double(1500.0)
    );
    assert_eq!(
        written_elements(&d, &Variant::Double(2.5)),
        Ok(vec![Value::Time(plc_core::Time::from_micros(2500))])
    );
    for bad in [
        Variant::Double(-1.0),
        Variant::Double(f64::NAN),
        Variant::Double(1e300),
    ] {
        assert_eq!(
            written_elements(&d, &bad),
            Err(StatusCode::BadOutOfRange),
            "{bad:?}"
        );
    }
    assert_eq!(
        written_elements(&d, &Variant::from("T#1s")),
        Err(StatusCode::BadTypeMismatch)
    );
}

#[test]
fn a_write_with_an_index_range_sets_the_selected_elements_in_row_major_order() {
    let list = var(
        "v",
        IecType::Int,
        &[6],
        Access::ReadWrite,
        Direction::Command,
    );
    let grid = var(
        "g",
        IecType::Int,
        &[2, 3],
        Access::ReadWrite,
        Direction::Command,
    );
    let ints = |v: &[i16]| Variant::from(v.to_vec());
    let range = |text: &str| text.parse::<NumericRange>().unwrap();
    let set = |var: &VarDescriptor, v: &Variant, r: &str| written_range(var, v, &range(r));
    let at = |pairs: &[(usize, i64)]| {
        Ok(pairs
            .iter()
            .map(|&(e, v)| (e, Value::Int(v)))
            .collect::<Vec<_>>())
    };
    assert_eq!(
        set(&list, &ints(&[7, 8, 9]), "2:4"),
        at(&[(2, 7), (3, 8), (4, 9)])
    );
    assert_eq!(set(&list, &Variant::Int16(5), "5"), at(&[(5, 5)]));
    assert_eq!(set(&list, &ints(&[5]), "0"), at(&[(0, 5)]));
    // Row 1, columns 0 and 1 of a 2 x 3 array: elements 3 and 4.
    assert_eq!(set(&grid, &ints(&[1, 2]), "1,0:1"), at(&[(3, 1), (4, 2)]));
    assert_eq!(
        set(&grid, &ints(&[1, 2, 3, 4]), "0:1,1:2"),
        at(&[(1, 1), (2, 2), (4, 3), (5, 4)])
    );
    let refused = |var: &VarDescriptor, v: &Variant, r: &str| set(var, v, r).unwrap_err();
    assert_eq!(
        refused(&list, &ints(&[1, 2]), "4:6"),
        StatusCode::BadIndexRangeNoData
    );
    assert_eq!(
        refused(&list, &ints(&[1, 2]), "2:4"),
        StatusCode::BadTypeMismatch
    );
    assert_eq!(
        refused(&grid, &ints(&[1]), "1"),
        StatusCode::BadIndexRangeInvalid
    );
    assert_eq!(
        refused(&grid, &ints(&[1]), "2,0"),
        StatusCode::BadIndexRangeNoData
    );
    assert_eq!(
        refused(&scalar(IecType::Int), &Variant::Int16(1), "0"),
        StatusCode::BadIndexRangeInvalid
    );
    // Without a range, the whole array.
    assert_eq!(
        written_range(&list, &ints(&[1, 2, 3, 4, 5, 6]), &NumericRange::None).map(|v| v.len()),
        Ok(6)
    );
}
