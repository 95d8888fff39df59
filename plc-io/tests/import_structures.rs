//! Structure types in a variable list: the `types` section's rules (each error class, named by
//! its JSON path), the CSV rows that declare types, and hostile type graphs (cycles, deep
//! chains, huge dimensions), which are refused in bounded time and never panic. The export of
//! structured variables: `export_structures.rs`. The golden module with structures is pinned
//! by `import.rs` and compiled by the examples' tests.
#![cfg(feature = "import")]

use plc_core::{GlobalMemory, PlcStruct};
use plc_io::import::{ImportErrors, Options, export_json, generate, generate_csv};
use proptest::prelude::*;
use serde_json::{Value, json};

fn errors(list: &Value) -> Vec<String> {
    match generate(&list.to_string(), &Options::default()) {
        Err(ImportErrors(e)) => e,
        Ok(g) => panic!("expected errors, got:\n{}", g.code),
    }
}

/// The one error of `list`, which must contain every part of `says`.
fn one_error(list: Value, says: &[&str]) {
    let e = errors(&list);
    assert_eq!(e.len(), 1, "{e:#?}");
    for part in says {
        assert!(e[0].contains(part), "{:?} lacks {part:?}", e[0]);
    }
}

fn axis() -> Value {
    json!({ "variables": { "pos": { "type": "f64" }, "homed": { "type": "bool" } } })
}

#[test]
fn a_structured_variable_and_an_array_of_them_import() {
    let list = json!({
        "types": { "Axis": axis() },
        "variables": { "lift": { "type": "Axis" }, "axes": { "type": "Axis", "dims": [3] } }
    });
    let code = generate(&list.to_string(), &Options::default())
        .unwrap()
        .code;
    assert!(
        code.contains("use plc_core::{GlobalMemory, PlcStruct};"),
        "{code}"
    );
    assert!(
        code.contains("#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]\npub struct Axis {")
    );
    assert!(code.contains("pub lift: Axis,"));
    assert!(code.contains("pub axes: [Axis; 3],"));
    // The structure before the program's struct that uses it.
    assert!(code.find("struct Axis").unwrap() < code.find("struct Gm").unwrap());
}

#[test]
fn a_member_error_is_named_by_its_path_in_the_types_section() {
    let list = json!({
        "types": { "Axis": { "variables": {
            "pos": { "type": "f64", "link": "ethercat.io.x" },
            "fault": { "type": "bool", "direction": "status" },
            "count": { "type": "u8", "initial": 300 }
        } } },
        "variables": { "lift": { "type": "Axis" } }
    });
    let e = errors(&list);
    assert_eq!(e.len(), 3, "{e:#?}");
    assert!(
        e[0].starts_with("types.Axis.variables.pos.link: "),
        "{}",
        e[0]
    );
    assert!(
        e[1].starts_with("types.Axis.variables.fault.direction: "),
        "{}",
        e[1]
    );
    assert!(
        e[2].starts_with("types.Axis.variables.count.initial: 300 is out of range"),
        "{}",
        e[2]
    );
}

#[test]
fn a_cycle_is_refused_naming_it() {
    let list = json!({
        "types": {
            "A": { "variables": { "b": { "type": "B" } } },
            "B": { "variables": { "x": { "type": "u8" }, "a": { "type": "A" } } }
        },
        "variables": { "v": { "type": "A" } }
    });
    one_error(
        list,
        &[
            "types.B.variables.a.type: ",
            "\"A\" contains itself: A.b -> B.a -> A",
        ],
    );
    let own = json!({
        "types": { "Node": { "variables": { "next": { "type": "Node", "dims": [2] } } } }
    });
    one_error(
        own,
        &["types.Node.variables.next.type: ", "Node.next -> Node"],
    );
}

#[test]
fn an_unknown_type_is_refused_with_the_nearest_name() {
    let list = json!({
        "types": { "Axis": axis() },
        "variables": { "lift": { "type": "Axsi" }, "other": { "type": "axis" } }
    });
    let e = errors(&list);
    assert_eq!(e.len(), 2, "{e:#?}");
    assert!(
        e[0].starts_with("variables.lift.type: unknown type \"Axsi\" (did you mean \"Axis\"?)"),
        "{}",
        e[0]
    );
    // Type names are exact: another case is a mistake the hint corrects.
    assert!(e[1].contains("(did you mean \"Axis\"?)"), "{}", e[1]);
}

#[test]
fn type_names_are_checked() {
    for (name, says) in [
        ("INT", "invalid type name \"INT\""),
        ("1axis", "invalid type name \"1axis\""),
        ("f64", "it is the name of a basic type"),
        ("ax__is", "invalid type name"),
        ("PlcStruct", "a name the generated module uses"),
        ("gm", "the type's Rust name \"Gm\""),
    ] {
        let list = json!({ "types": { name: axis() }, "variables": { "v": { "type": name } } });
        let e = errors(&list);
        assert!(
            e.iter()
                .any(|m| m.starts_with(&format!("types.{name}: ")) && m.contains(says)),
            "{name}: {e:#?}"
        );
    }
    let twice = format!(
        r#"{{ "types": {{ "Axis": {a}, "AXIS": {a} }}, "variables": {{ "v": {{ "type": "Axis" }} }} }}"#,
        a = axis()
    );
    let e = errors(&serde_json::from_str(&twice).unwrap());
    assert_eq!(e.len(), 1, "{e:#?}");
    assert!(
        e[0].starts_with("types.AXIS: the type \"AXIS\" is declared already as \"Axis\""),
        "{}",
        e[0]
    );
    let same_rust = json!({ "types": { "axis_t": axis(), "AxisT": axis() } });
    one_error(
        same_rust,
        &[
            "types.AxisT: ",
            "Rust name \"AxisT\" is that of the type \"axis_t\"",
        ],
    );
}

#[test]
fn a_type_has_members_and_only_known_fields() {
    let list = json!({ "types": {
        "Empty": { "description": "nothing", "variables": {} },
        "Odd": { "description": 3, "members": {}, "variables": { "a": { "type": "u8" } } }
    } });
    let e = errors(&list);
    assert_eq!(e.len(), 3, "{e:#?}");
    assert!(e[0].starts_with("types.Empty.variables: a structure needs at least one member"));
    assert!(e[1].starts_with("types.Odd.description: expected a string, found 3"));
    assert!(
        e[2].starts_with("types.Odd.members: unknown field: use one of description, variables")
    );
}

#[test]
fn a_structured_variable_has_no_value_or_io_of_its_own() {
    let list = json!({
        "types": { "Axis": axis() },
        "variables": {
            "state": { "type": "u16" },
            "a": { "type": "Axis", "initial": 1 },
            "b": { "type": "Axis", "nonvolatile": true },
            "c": { "type": "Axis", "link": "ethercat.io.x" },
            "d": { "type": "Axis", "at": "%IW4" },
            "e": { "type": "Axis", "source": "state", "bit": 2 },
            "f": { "type": "bool", "source": "a", "bit": 0 },
            "g": { "type": "Axis", "max_length": 8 }
        }
    });
    let e = errors(&list);
    let expected = [
        "variables.a.initial: \"a\" is a structure: give `initial` on its members, in the structure's declaration",
        "variables.b.nonvolatile: \"b\" is a structure: it cannot be `nonvolatile` as a whole",
        "variables.c.link: \"c\" is a structure: a link connects one basic variable to one entry",
        "variables.d.at: \"d\" is a structure: `at` locates one channel",
        "variables.e.source: \"e\" is mapped to a bit, so its type must be bool",
        "variables.f.source: the source \"a\" must be an integer",
        "variables.g.max_length: only strings have a max_length",
    ];
    assert_eq!(e.len(), expected.len(), "{e:#?}");
    for (got, want) in e.iter().zip(expected) {
        assert!(got.starts_with(want), "{got:?} is not {want:?}");
    }
}

#[test]
fn arrays_of_structures_have_the_limits_of_arrays() {
    let list = json!({
        "types": { "Axis": axis() },
        "variables": {
            "a": { "type": "Axis", "dims": [2, 2, 2, 2] },
            "b": { "type": "Axis", "dims": [65536] },
            "c": { "type": "Axis", "dims": [0] },
            "d": { "type": "Axis", "dims": [65535] }
        }
    });
    let e = errors(&list);
    assert_eq!(e.len(), 3, "{e:#?}");
    assert!(e[0].starts_with("variables.a.dims: "), "{}", e[0]);
    assert!(e[1].starts_with("variables.b.dims: "), "{}", e[1]);
    assert!(e[2].starts_with("variables.c.dims: "), "{}", e[2]);
}

/// `n` types, each holding the one before it.
fn chain(n: usize) -> Value {
    let mut types = serde_json::Map::new();
    types.insert("T0".into(), axis());
    for i in 1..n {
        let prev = format!("T{}", i - 1);
        types.insert(
            format!("T{i}"),
            json!({ "variables": { "inner": { "type": prev } } }),
        );
    }
    json!({ "types": types, "variables": { "top": { "type": format!("T{}", n - 1) } } })
}

#[test]
fn nesting_stops_at_eight_levels() {
    generate(&chain(8).to_string(), &Options::default()).unwrap();
    // The ninth level is refused where it is written (a member of 8 levels), and so is the
    // variable that holds it, as the derive refuses each such field.
    let e = errors(&chain(9));
    assert_eq!(e.len(), 2, "{e:#?}");
    assert!(e[0].starts_with("types.T8.variables.inner.type: the type of \"inner\" nests structures too deep: at most 8 levels"), "{}", e[0]);
    assert!(
        e[1].starts_with("variables.top.type: the type of \"top\" nests structures too deep"),
        "{}",
        e[1]
    );
}

#[test]
fn a_deep_chain_of_types_is_refused_in_bounded_time_without_recursion() {
    let started = std::time::Instant::now();
    let e = errors(&chain(20_000));
    assert!(
        e.iter().all(|m| m.contains("nests structures too deep")),
        "{:?}",
        &e[..2]
    );
    // One per member past the limit (types T8 and later) and one for the variable, as the
    // derive reports each field.
    assert_eq!(e.len(), 20_000 - 8 + 1);
    assert!(started.elapsed().as_secs() < 20, "{:?}", started.elapsed());
}

#[test]
fn an_image_of_four_gib_is_refused() {
    let list = json!({
        "types": {
            "Big": { "variables": { "a": { "type": "f64", "dims": [65535] } } },
            "Huge": { "variables": { "b": { "type": "Big", "dims": [65535] } } }
        },
        "variables": { "v": { "type": "Big", "dims": [9000] } }
    });
    let e = errors(&list);
    assert_eq!(e.len(), 2, "{e:#?}");
    assert!(
        e[0].starts_with("types.Huge: the image of \"Huge\" is 4 GiB or more"),
        "{}",
        e[0]
    );
    assert!(
        e[1].starts_with("the image of `Gm` is 4 GiB or more"),
        "{}",
        e[1]
    );
}

#[test]
fn a_sheet_declares_types_by_struct_rows_and_member_rows() {
    let csv = "name,type,description,dims,initial\r\n\
               Axis,STRUCT,One axis,,\r\n\
               Axis.pos,f64,Actual position,,\r\n\
               Axis.target,f64,,,250.0\r\n\
               lift,Axis,,,\r\n\
               axes,Axis,,3,\r\n";
    let json = json!({
        "types": { "Axis": { "description": "One axis", "variables": {
            "pos": { "type": "f64", "description": "Actual position" },
            "target": { "type": "f64", "initial": 250.0 }
        } } },
        "variables": { "lift": { "type": "Axis" }, "axes": { "type": "Axis", "dims": [3] } }
    });
    let o = Options::default();
    assert_eq!(
        generate_csv(csv, &o).unwrap().code,
        generate(&json.to_string(), &o).unwrap().code
    );
}

#[test]
fn a_sheet_s_structure_errors_name_the_line() {
    let csv = "name,type,link\r\n\
               Axsi.pos,f64,\r\n\
               Axis,STRUCT,ethercat.io.x\r\n\
               Axis.pos,f64,ethercat.io.y\r\n\
               Axis.a.b,f64,\r\n\
               lift,Axis,\r\n";
    let e = match generate_csv(csv, &Options::default()) {
        Err(ImportErrors(e)) => e,
        Ok(g) => panic!("{}", g.code),
    };
    assert_eq!(e.len(), 4, "{e:#?}");
    assert!(e[0].starts_with("line 2, column name: \"Axsi.pos\" is a member of the type \"Axsi\", which no row declares"), "{}", e[0]);
    assert!(
        e[1].starts_with("line 3, type Axis, column link: a STRUCT row declares a type"),
        "{}",
        e[1]
    );
    assert!(
        e[2].starts_with("line 4, variable Axis.pos, column link: "),
        "{}",
        e[2]
    );
    assert!(
        e[3].starts_with("line 5, column name: \"Axis.a.b\" is not a member"),
        "{}",
        e[3]
    );
}

/// A type graph: `n` types whose members use types by index (`edges[i]` for type `i`);
/// `forward` edges allowed or not (without them the graph has no cycle).
fn type_graph(edges: &[Vec<usize>], dims: &[u64]) -> Value {
    let n = edges.len();
    let mut types = serde_json::Map::new();
    for (i, uses) in edges.iter().enumerate() {
        let mut members = serde_json::Map::new();
        members.insert("x".into(), json!({ "type": "u8" }));
        for (k, &u) in uses.iter().enumerate() {
            let d = dims[(i + k) % dims.len()];
            members.insert(
                format!("m{k}"),
                json!({ "type": format!("T{}", u % n), "dims": [d] }),
            );
        }
        types.insert(format!("T{i}"), json!({ "variables": members }));
    }
    json!({ "types": types, "variables": { "top": { "type": format!("T{}", n - 1) } } })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Acyclic graphs (each type uses only earlier ones) within the limits import, each type
    /// after the types it uses; any graph at all gives code or errors, never a panic.
    #[test]
    fn type_graphs_import_or_are_refused_without_panic(
        edges in prop::collection::vec(prop::collection::vec(0usize..12, 0..4), 1..12),
        dims in prop::collection::vec(1u64..4, 1..4),
    ) {
        let acyclic: Vec<Vec<usize>> = edges
            .iter()
            .enumerate()
            .map(|(i, e)| e.iter().filter(|&&u| u < i).copied().collect())
            .collect();
        let list = type_graph(&acyclic, &dims);
        match generate(&list.to_string(), &Options::default()) {
            Ok(g) => {
                for (i, uses) in acyclic.iter().enumerate() {
                    let own = g.code.find(&format!("pub struct T{i} ")).unwrap();
                    for u in uses {
                        let used = g.code.find(&format!("pub struct T{u} ")).unwrap();
                        prop_assert!(used < own, "T{} after T{}", u, i);
                    }
                }
            }
            // Only the depth limit can refuse an acyclic graph of small arrays.
            Err(e) => prop_assert!(
                e.0.iter().all(|m| m.contains("nests structures too deep")),
                "{e}"
            ),
        }
        let any = type_graph(&edges, &dims);
        let _ = generate(&any.to_string(), &Options::default());
    }
}

#[test]
fn the_standard_function_blocks_are_named_by_their_iec_names_without_a_declaration() {
    let list = json!({ "variables": {
        "start_delay": { "type": "TON" },
        "button": { "type": "R_TRIG" },
        "timeouts": { "type": "TP", "dims": [3] },
        "latch": { "type": "RS" },
        "parts": { "type": "CTUD" }
    } });
    let code = generate(&list.to_string(), &Options::default())
        .unwrap()
        .code;
    // Only the program's struct is generated, and nothing it does not use is imported.
    assert!(code.starts_with("// Generated"), "{code}");
    assert!(code.contains("use plc_core::GlobalMemory;\n"), "{code}");
    assert!(!code.contains("PlcStruct"), "{code}");
    for field in [
        "pub start_delay: plc_core::fb::Ton,",
        "pub button: plc_core::fb::RTrig,",
        "pub timeouts: [plc_core::fb::Tp; 3],",
        "pub latch: plc_core::fb::Rs,",
        "pub parts: plc_core::fb::Ctud,",
    ] {
        assert!(code.contains(field), "{field} in\n{code}");
    }
    // The same from a sheet.
    let csv = "name,type,dims\r\nstart_delay,TON,\r\ntimeouts,TP,3\r\n";
    let code = generate_csv(csv, &Options::default()).unwrap().code;
    assert!(
        code.contains("pub timeouts: [plc_core::fb::Tp; 3],"),
        "{code}"
    );
}

#[test]
fn a_function_block_variable_has_the_rules_of_a_structured_one() {
    one_error(
        json!({ "variables": { "delay": { "type": "TON", "nonvolatile": true } } }),
        &["variables.delay.nonvolatile"],
    );
    one_error(
        json!({ "variables": { "delay": { "type": "TON", "initial": 5 } } }),
        &["variables.delay.initial"],
    );
    // Type names are exact: the nearest standard name is suggested.
    one_error(
        json!({ "variables": { "delay": { "type": "Ton" } } }),
        &["variables.delay.type", "did you mean \"TON\"?"],
    );
    // A list cannot declare a type of a standard block's name, in any case.
    one_error(
        json!({ "types": { "ctu": axis() }, "variables": { "c": { "type": "ctu" } } }),
        &[
            "types.ctu",
            "standard function block of IEC 61131-3",
            "\"CTU\"",
        ],
    );
}

#[test]
fn a_structure_holding_function_blocks_imports_and_its_export_names_them() {
    #[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
    struct Station {
        delay: plc_core::fb::Ton,
        edges: [plc_core::fb::FTrig; 2],
        count: u16,
    }
    #[derive(GlobalMemory, Debug, Clone)]
    struct Line {
        station: Station,
        parts: plc_core::fb::Ctu,
    }
    let json: Value = serde_json::from_str(&export_json::<Line>().unwrap()).unwrap();
    let types: Vec<&String> = json["types"].as_object().unwrap().keys().collect();
    assert_eq!(types, ["Station"], "standard blocks are not declared");
    assert_eq!(
        json["types"]["Station"]["variables"]["delay"]["type"],
        "TON"
    );
    assert_eq!(
        json["types"]["Station"]["variables"]["edges"]["type"],
        "F_TRIG"
    );
    assert_eq!(json["variables"]["parts"]["type"], "CTU");
    let code = generate(&json.to_string(), &Options::default())
        .unwrap()
        .code;
    assert!(
        code.contains("pub edges: [plc_core::fb::FTrig; 2],"),
        "{code}"
    );
    assert!(code.contains("pub parts: plc_core::fb::Ctu,"), "{code}");
}
