//! The CSV front end of the importer: the same variables as JSON give the same code, RFC 4180
//! quoting both ways, every CSV error class located by line, variable and column, the export of
//! a compiled type, and no panic on any input.
#![cfg(feature = "import")]

use plc_core::{FixedString, GlobalMemory};
use plc_io::import::{
    COLUMNS, ImportErrors, Options, export_csv, export_json, generate, generate_csv,
};
use proptest::prelude::*;

const HEADER: &str = "name,type,direction,link,description,initial,source,bit,max_length,nonvolatile,read_only,at,dims,ux,quantity,unit,deadband";

fn csv_errors(csv: &str) -> Vec<String> {
    match generate_csv(csv, &Options::default()) {
        Err(ImportErrors(e)) => e,
        Ok(g) => panic!("expected errors, got:\n{}", g.code),
    }
}

/// The rows under the full header, CRLF line ends as RFC 4180 writes them.
fn table(rows: &[&str]) -> String {
    let mut t = format!("{HEADER}\r\n");
    for r in rows {
        t.push_str(r);
        t.push_str("\r\n");
    }
    t
}

#[test]
fn the_columns_are_the_frameworks_then_the_rest() {
    assert_eq!(COLUMNS.join(","), HEADER);
}

#[test]
fn csv_gives_the_same_code_as_the_same_json() {
    let json = r#"{ "variables": {
        "impact67_0_digital_inputs": { "type": "u16", "link": "ethercat.impact67_0.digital_inputs", "direction": "input" },
        "ls_lift_neg": { "type": "bool", "source": "impact67_0_digital_inputs", "bit": 2 },
        "info_test_id": { "type": "string", "max_length": 32, "initial": "TEST-001", "description": "Test identifier" },
        "press_home_offset_mm": { "type": "f64", "nonvolatile": true, "initial": 12.5 },
        "tests_completed": { "type": "u32", "read_only": true, "initial": 0 },
        "mode_word": { "type": "WORD", "initial": 3 },
        "analog_in": { "type": "i16", "at": "%IW4" },
        "lamp": { "type": "bool", "initial": false },
        "recipe_speeds": { "type": "f32", "dims": [3, 4] }
    } }"#;
    let csv = table(&[
        "impact67_0_digital_inputs,u16,input,ethercat.impact67_0.digital_inputs,,,,,,,,,",
        "ls_lift_neg,bool,,,,,impact67_0_digital_inputs,2,,,,,",
        "info_test_id,string,,,Test identifier,TEST-001,,,32,,,,",
        "press_home_offset_mm,f64,,,,12.5,,,,true,,,",
        "tests_completed,u32,,,,0,,,,,TRUE,,",
        "mode_word,WORD,,,,3,,,,,,,",
        "analog_in,i16,,,,,,,,,,%IW4,",
        "lamp,bool,,,,False,,,,,,,",
        "recipe_speeds,f32,,,,,,,,,,,\"[3, 4]\"",
    ]);
    let o = Options::default();
    assert_eq!(
        generate_csv(&csv, &o).unwrap().code,
        generate(json, &o).unwrap().code
    );
}

#[test]
fn columns_may_come_in_any_order_and_case_and_rows_may_be_short() {
    // A byte order mark (spreadsheets write one), LF line ends, trailing empty rows.
    let csv = "\u{feff}Type, NAME ,Bit,Source\nu16,w\nbool,b,3,w\n,,,\n\n";
    let g = generate_csv(csv, &Options::default()).unwrap();
    assert!(g.code.contains("pub w: u16,"), "{}", g.code);
    assert!(
        g.code.contains("#[plc(source = \"w\", bit = 3"),
        "{}",
        g.code
    );
}

#[test]
fn dimensions_are_written_as_a_list_or_plain_numbers() {
    for cell in ["3", "\"3,4\"", "\"[3, 4]\"", " [ 2 ] "] {
        let csv = format!("name,type,dims\r\na,u8,{cell}\r\n");
        let g = generate_csv(&csv, &Options::default()).unwrap();
        assert!(
            g.code.contains("pub a: [u8; 3],")
                || g.code.contains("pub a: [[u8; 4]; 3],")
                || g.code.contains("pub a: [u8; 2],"),
            "{cell}: {}",
            g.code
        );
    }
}

/// Commas, doubled quotes, CR LF and lone LF inside quoted cells are data, both in the text of a
/// description and in a string's initial value.
#[test]
fn quoted_cells_keep_commas_quotes_and_line_breaks() {
    let csv = table(&[
        "label,string,,,\"Label, as printed\",\"say \"\"hi\"\", then\r\nwait\nok\",,,,,,,",
        "note,string,,,\"two\r\nlines\",,,,,,,,",
    ]);
    let g = generate_csv(&csv, &Options::default()).unwrap();
    assert!(g.code.contains("/// Label, as printed\n"), "{}", g.code);
    assert!(
        g.code
            .contains(r#"#[plc(initial = "say \"hi\", then\r\nwait\nok")]"#),
        "{}",
        g.code
    );
    assert!(
        g.code.contains("    /// two\n    /// lines\n"),
        "{}",
        g.code
    );
}

/// A compiled type with text that needs quoting, exported as CSV.
#[derive(GlobalMemory, Debug, Clone)]
struct Quoting {
    /// Offset, in "mm"
    #[plc(nonvolatile, initial = 12.5)]
    offset: f64,
    #[plc(initial = "a,b \"c\"\r\nd", description = "")]
    label: FixedString<32>,
    #[plc(link = "ethercat.io.inputs", direction = "input")]
    inputs: u16,
    #[plc(source = "inputs", bit = 15, read_only)]
    flag: bool,
    grid: [[i8; 2]; 3],
}

#[test]
fn the_export_quotes_as_rfc_4180_says() {
    let csv = export_csv::<Quoting>().unwrap();
    assert_eq!(
        csv,
        format!(
            "{HEADER}\r\n\
             offset,f64,,,\"Offset, in \"\"mm\"\"\",12.5,,,,true,,,,,,,\r\n\
             label,string,,,,\"a,b \"\"c\"\"\r\nd\",,,32,,,,,,,,\r\n\
             inputs,u16,input,ethercat.io.inputs,,,,,,,,,,,,,\r\n\
             flag,bool,,,,,inputs,15,,,true,,,,,,\r\n\
             grid,i8,,,,,,,,,,,\"[3,2]\",,,,\r\n"
        )
    );
}

/// compiled type -> CSV -> Rust gives the code that compiled type -> JSON -> Rust gives: the two
/// exports say the same.
#[test]
fn the_csv_and_json_exports_import_to_the_same_code() {
    let o = Options::default();
    assert_eq!(
        generate_csv(&export_csv::<Quoting>().unwrap(), &o)
            .unwrap()
            .code,
        generate(&export_json::<Quoting>().unwrap(), &o)
            .unwrap()
            .code
    );
}

/// A measured value with its engineering unit and reporting deadband, beside an alarm's own
/// deadband.
#[derive(GlobalMemory, Debug, Clone)]
struct Reported {
    #[plc(
        unit = "kN",
        deadband = 0.5,
        alarm(text = "Overload", high = 90.0, deadband = 2.0)
    )]
    force: f32,
    #[plc(unit = "°C", deadband = 1)]
    temperatures: [i16; 2],
    count: u32,
}

/// `unit` and `deadband` are columns of their own, exported and read back; the alarm's
/// deadband stays in its own column.
#[test]
fn units_and_deadbands_round_trip_through_csv_and_json() {
    let csv = export_csv::<Reported>().unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert!(lines[0].starts_with(&format!("{HEADER},alarm")), "{csv}");
    let force = "force,f32,,,,,,,,,,,,,,kN,0.5,Overload,";
    let temperatures = "temperatures,i16,,,,,,,,,,,[2],,,°C,1.0,";
    assert!(lines[1].starts_with(force), "{csv}");
    assert!(lines[2].starts_with(temperatures), "{csv}");
    let o = Options::default();
    let from_csv = generate_csv(&csv, &o).unwrap().code;
    for key in [
        "unit = \"kN\",\n        deadband = 0.5,",
        "alarm(text = \"Overload\", high = 90.0, deadband = 2.0)",
        "unit = \"°C\", deadband = 1,",
    ] {
        assert!(from_csv.contains(key), "{key} missing:\n{from_csv}");
    }
    let from_json = generate(&export_json::<Reported>().unwrap(), &o)
        .unwrap()
        .code;
    assert_eq!(from_csv, from_json);
}

/// A deadband cell that is no number, a negative one and units on what is no number: each
/// located by line, variable and column, in the derive's words.
#[test]
fn unit_and_deadband_cells_are_checked() {
    let errors = csv_errors(&table(&[
        "a,f32,,,,,,,,,,,,,,kN,fast",
        "b,f32,,,,,,,,,,,,,,,-1",
        "c,bool,,,,,,,,,,,,,,mm,",
        "d,WORD,,,,,,,,,,,,,,,0.5",
    ]));
    assert_eq!(
        errors,
        [
            "line 2, variable a, column deadband: expected a number such as 0.5, found \"fast\"",
            "line 3, variable b, column deadband: `deadband = -1` on \"b\" is negative: the \
             reporting deadband is how far a number must move before a change is published (0: \
             every change); give 0 or more, or remove it for the publisher's default",
            "line 4, variable c, column unit: `unit` cannot be declared on \"c\" (bool, BOOL): a \
             bool is true or false, not a quantity; remove `unit` (an engineering unit is for \
             integers, REAL and LREAL)",
            "line 5, variable d, column deadband: `deadband` cannot be declared on \"d\" (u16, \
             WORD): WORD is a bit string, a set of bits rather than a quantity (declared without \
             `iec_type`, the variable is an integer), and each of its changes is published; \
             remove `deadband` (a reporting deadband is for integers, REAL and LREAL)",
        ]
    );
}

#[test]
fn quoting_mistakes_are_errors_with_their_line() {
    let cases = [
        (
            table(&["a,u8,,,\"never closed,,,,,,,,", "b,u8,,,,,,,,,,,"]),
            "line 2: a quoted field is not closed",
        ),
        (
            table(&["a,u8,,,5\" pipe,,,,,,,,"]),
            "line 2: a double quote inside an unquoted field",
        ),
        (
            table(&["a,u8,,,,,,,,,,,", "b,u8,,,\"x\"y,,,,,,,,"]),
            "line 3: text after the closing quote",
        ),
        // The line of a mistake after a quoted line break counts that break.
        (
            table(&["a,u8,,,\"one\r\ntwo\",,,,,,,,", "b,u8,,,x\"y,,,,,,,,"]),
            "line 4: a double quote inside an unquoted field",
        ),
    ];
    for (csv, expected) in cases {
        let e = csv_errors(&csv);
        assert_eq!(e.len(), 1, "{e:?}");
        assert!(e[0].starts_with(expected), "{csv:?}\n{e:?}");
    }
}

#[test]
fn header_mistakes_are_errors() {
    let cases = [
        ("", "the file is empty"),
        ("\u{feff}", "the file is empty"),
        (
            "name,type,colour\r\na,u8,red\r\n",
            "line 1, column 3: unknown column \"colour\": use name, type,",
        ),
        (
            "name,type,Type\r\na,u8,u8\r\n",
            "line 1: column \"type\" is named twice",
        ),
        ("type,link\r\nu8,\r\n", "line 1: no \"name\" column"),
        ("name,link\r\na,\r\n", "line 1: no \"type\" column"),
        // No header at all: the first variable is read as one, and said to be no column.
        ("a,u8\r\n", "line 1, column 1: unknown column \"a\""),
    ];
    for (csv, expected) in cases {
        let e = csv_errors(csv);
        assert!(e[0].starts_with(expected), "{csv:?}\n{e:?}");
    }
}

#[test]
fn row_mistakes_are_errors_the_other_rows_are_still_checked_all_in_file_order() {
    let e = csv_errors(&table(&[
        "a,u8,,,,,,,,,,,,,,,,extra",
        ",u8,,,,,,,,,,,",
        "b,u8,,,,300,,,,,,,",
        "B,u8,,,,,,,,,,,",
    ]));
    assert_eq!(
        e,
        [
            "line 2: 18 cells but the header names 17 columns: put a cell that holds a comma in double quotes",
            "line 3, column name: empty: every row needs the variable's name",
            "line 4, variable b, column initial: 300 is out of range for USINT (u8 holds 0..=255)",
            "line 5, variable B: declared twice: \"B\" is already used by \"b\" (line 4), and names are case-insensitive; rename one",
        ]
    );
}

/// The checks are the JSON importer's; CSV words them with the line, the variable and the
/// column.
#[test]
fn cell_errors_name_the_line_variable_and_column() {
    let cases = [
        (
            "a,u17,,,,,,,,,,,",
            "line 2, variable a, column type: unknown type \"u17\"",
        ),
        (",,,,,,,,,,,,", ""), // skipped: an empty row
        ("a,,,,,,,,,,,,", "line 2, variable a, column type: missing"),
        (
            "a,u8,in,,,,,,,,,,",
            "line 2, variable a, column direction: unknown direction \"in\"",
        ),
        (
            "a,u8,,io,,,,,,,,,",
            "line 2, variable a, column link: invalid link \"io\"",
        ),
        (
            "a,u8,,,,x,,,,,,,",
            "line 2, variable a, column initial: \"x\" is not a USINT value",
        ),
        (
            "a,bool,,,,1,,,,,,,",
            "line 2, variable a, column initial: 1 is not a BOOL value",
        ),
        (
            "a,f32,,,,1e39,,,,,,,",
            "line 2, variable a, column initial: 1e+39 is out of range for REAL",
        ),
        (
            "a,string,,,,,,,300,,,,",
            "line 2, variable a, column max_length: 300 is not a capacity",
        ),
        (
            "a,string,,,,,,,many,,,,",
            "line 2, variable a, column max_length: \"many\" is not a capacity",
        ),
        (
            "a,u8,,,,,,,,yes,,,",
            "line 2, variable a, column nonvolatile: expected true or false, found \"yes\"",
        ),
        (
            "a,u8,,,,,,,,,1,,",
            "line 2, variable a, column read_only: expected true or false, found \"1\"",
        ),
        (
            "a,u8,,,,,,,,,,%MB4,",
            "line 2, variable a, column at: \"%MB4\" is in the M area",
        ),
        (
            "a,u8,,,,,,,,,,,0",
            "line 2, variable a, column dims: an array needs at least one item in each dimension",
        ),
        (
            "a,u8,,,,,,,,,,,\"2,x\"",
            "line 2, variable a, column dims: [2,\"x\"] is not a list",
        ),
        (
            "a,u8,,,,,,,,,,,[]",
            "line 2, variable a, column dims: 0 dimensions given",
        ),
        (
            "a,bool,,,,,w,,,,,,",
            "line 2, variable a, column source: needs `bit`",
        ),
        (
            "a,bool,,,,,,x,,,,,",
            "line 2, variable a, column bit: \"x\" is not a bit number 0..=63",
        ),
        (
            "ton,bool,,,,,,,,,,,",
            "line 2, variable ton: invalid variable name",
        ),
        (
            "self,u8,,,,,,,,,,,",
            "line 2, variable self: this name cannot be a Rust field",
        ),
    ];
    for (row, expected) in cases {
        if expected.is_empty() {
            continue;
        }
        let e = csv_errors(&table(&[row]));
        assert!(
            e.iter().any(|m| m.starts_with(expected)),
            "{row}\nexpected `{expected}` in {e:#?}"
        );
    }
}

#[test]
fn the_format_example_message_through_csv() {
    let e = csv_errors(&table(&[
        "impact67_0_digital_inputs,u16,,ethercat.impact67_0.digital_inputs,,,,,,,,,",
        "ls_lift_neg,bool,,,,,impact67_0_digital_inputs,16,,,,,",
    ]));
    assert_eq!(
        e,
        [
            "line 3, variable ls_lift_neg, column bit: 16 is out of range for source \"impact67_0_digital_inputs\" (u16 has bits 0..=15)"
        ]
    );
}

#[test]
fn warnings_are_located_too() {
    let g = generate_csv(
        &table(&[
            "a,u8,,ethercat.io.x,,,,,,,,,",
            "\"b\",u8,,ethercat.io.x,,,,,,,,,",
        ]),
        &Options::default(),
    )
    .unwrap();
    assert_eq!(g.warnings.len(), 1);
    assert!(
        g.warnings[0].starts_with(
            "line 3, variable b, column link: \"ethercat.io.x\" is also linked by \"a\""
        ),
        "{:?}",
        g.warnings
    );
}

/// A CSV cell: anything, often with the characters that need quoting.
fn cell() -> impl Strategy<Value = String> {
    prop_oneof![
        Just(String::new()),
        prop::sample::select(vec![
            "u16",
            "bool",
            "string",
            "f32",
            "WORD",
            "w",
            "b",
            "input",
            "true",
            "3",
            "64",
            "[2,3]",
            "%IW4",
            "%QX0.1",
            "ethercat.io.x",
            "1e39",
            "-1",
        ])
        .prop_map(String::from),
        "[a-z,\"\r\n ]{0,8}",
        "\\PC{0,10}",
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Rows of random cells, written with correct quoting: an answer, never a panic.
    #[test]
    fn no_table_makes_the_csv_importer_panic(
        rows in prop::collection::vec(prop::collection::vec(cell(), 0..15), 0..6),
    ) {
        let mut w = csv::WriterBuilder::new().flexible(true).from_writer(Vec::new());
        w.write_record(COLUMNS).unwrap();
        for r in &rows {
            w.write_record(r).unwrap();
        }
        let text = String::from_utf8(w.into_inner().unwrap()).unwrap();
        if let Err(ImportErrors(e)) = generate_csv(&text, &Options::default()) {
            prop_assert!(!e.is_empty());
            prop_assert!(!e.iter().any(|m| m.contains("please report")), "{e:?}");
        }
    }

    /// Any text at all.
    #[test]
    fn no_text_makes_the_csv_importer_panic(text in "[a-z0-9,\"\r\n ]{0,200}|\\PC{0,200}") {
        let _ = generate_csv(&text, &Options::default());
    }
}
