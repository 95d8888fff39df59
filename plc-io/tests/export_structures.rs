//! The export of structured variables: each structure type once, before the types that use
//! it; one name for two different types refused; a descriptor nesting too deep refused.
#![cfg(feature = "import")]

use plc_core::{GlobalMemory, PlcStruct};
use plc_io::import::{descriptor_to_json, export_json};
use plc_io::shm::LayoutDescriptor;
use serde_json::Value;

mod one {
    /// An axis with a position.
    #[derive(plc_core::PlcStruct, Debug, Clone, Copy, PartialEq)]
    pub struct Axis {
        /// Position.
        pub pos: f64,
    }
}

mod other {
    /// Another structure that calls itself `Axis`.
    #[derive(plc_core::PlcStruct, Debug, Clone, Copy, PartialEq)]
    #[plc(name = "Axis")]
    pub struct Carriage {
        /// Speed.
        pub speed: f32,
    }
}

#[derive(GlobalMemory, Debug, Clone)]
struct TwoAxes {
    lift: one::Axis,
    axes: [one::Axis; 2],
    carriage: other::Carriage,
}

#[test]
fn an_export_writes_each_type_once_and_refuses_one_name_for_two_types() {
    #[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
    struct Pair {
        a: one::Axis,
        b: u8,
    }
    #[derive(GlobalMemory, Debug, Clone)]
    struct Shared {
        lift: one::Axis,
        pair: [Pair; 2],
    }
    let json: Value = serde_json::from_str(&export_json::<Shared>().unwrap()).unwrap();
    let names: Vec<&String> = json["types"].as_object().unwrap().keys().collect();
    assert_eq!(
        names,
        ["Axis", "Pair"],
        "each once, a type before the types using it"
    );
    let e = export_json::<TwoAxes>().unwrap_err();
    assert!(
        e.contains("two structure types are named \"Axis\" with different members (one in \"lift\", one in \"carriage\")"),
        "{e}"
    );
}

#[test]
fn an_export_of_a_descriptor_nesting_too_deep_fails() {
    let mut desc = LayoutDescriptor::of::<Deep>();
    // Nest the one member inside itself past the limit, as a damaged descriptor could.
    let mut v = desc.variables[0].clone();
    for _ in 0..12 {
        let mut outer = v.clone();
        outer.members = vec![v];
        v = outer;
    }
    desc.variables[0] = v;
    let e = descriptor_to_json(&desc).unwrap_err();
    assert!(
        e.contains("nests structures more than 8 levels deep"),
        "{e}"
    );
}

#[derive(GlobalMemory, Debug, Clone)]
struct Deep {
    lift: one::Axis,
}
