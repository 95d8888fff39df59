// The agreement table: every declaration rule once, and valid declarations at each limit,
// each written as a Rust struct and (where the format has one) as the same JSON variable list,
// with the issue kinds the checker must give for both. The derive's tests read the `rust`
// column through `syn::parse_str` and its own syn-to-model conversion, the importer's tests
// the `json` column through its JSON-to-model conversion; both must give `kinds`, in any
// order. Adding a rule means adding a row. Included by the tests of plc-rules, plc-derive and
// plc-io (`include!`), so it holds only this table.

/// One declaration, in both forms (each crate's test reads its own column).
#[allow(dead_code)]
struct Row {
    /// What the row shows.
    rule: &'static str,
    /// The struct, as a user writes it (without the derive attribute).
    rust: &'static str,
    /// The members of the list's `variables` object (of a type's `variables` in its `types`
    /// section, `"Axis": { "variables": { .. } }`, for a row declaring a structure type), or
    /// `None` where the format cannot say it (with the reason in `rule`).
    json: Option<&'static str>,
    /// The issue kinds both give (`IssueKind::name`).
    kinds: &'static [&'static str],
}

const ROWS: &[Row] = &[
    Row {
        rule: "a valid declaration of every basic type",
        rust: "struct Gm { a: bool, b: u8, c: i16, d: u32, e: i64, f: f32, g: f64, h: FixedString<8> }",
        json: Some(r#""a": {"type": "bool"}, "b": {"type": "u8"}, "c": {"type": "i16"}, "d": {"type": "u32"}, "e": {"type": "i64"}, "f": {"type": "f32"}, "g": {"type": "f64"}, "h": {"type": "string", "max_length": 8}"#),
        kinds: &[],
    },
    Row {
        rule: "a reserved name (a standard function block)",
        rust: "struct Gm { ton: bool }",
        json: Some(r#""ton": {"type": "bool"}"#),
        kinds: &["BadName"],
    },
    Row {
        rule: "a name with two consecutive underscores",
        rust: "struct Gm { motor__speed: i32 }",
        json: Some(r#""motor__speed": {"type": "i32"}"#),
        kinds: &["BadName"],
    },
    Row {
        rule: "a name starting with a digit",
        rust: "struct Gm { #[plc(name = \"1st_axis\")] first_axis: i32 }",
        json: Some(r#""1st_axis": {"type": "i32"}"#),
        kinds: &["BadName"],
    },
    Row {
        rule: "a name given twice, in another case",
        rust: "struct Gm { speed: i32, #[plc(name = \"SPEED\")] speed_2: i32 }",
        json: Some(r#""speed": {"type": "i32"}, "SPEED": {"type": "i32"}"#),
        kinds: &["DuplicateName"],
    },
    Row {
        rule: "a string capacity of 0",
        rust: "struct Gm { label: FixedString<0> }",
        json: Some(r#""label": {"type": "string", "max_length": 0}"#),
        kinds: &["BadCapacity"],
    },
    Row {
        rule: "a string capacity of 256",
        rust: "struct Gm { label: FixedString<256> }",
        json: Some(r#""label": {"type": "string", "max_length": 256}"#),
        kinds: &["BadCapacity"],
    },
    Row {
        rule: "string capacities at the limits, 1 and 255",
        rust: "struct Gm { a: FixedString<1>, b: FixedString<255> }",
        json: Some(r#""a": {"type": "string", "max_length": 1}, "b": {"type": "string", "max_length": 255}"#),
        kinds: &[],
    },
    Row {
        rule: "an array of four dimensions",
        rust: "struct Gm { grid: [[[[u8; 2]; 2]; 2]; 2] }",
        json: Some(r#""grid": {"type": "u8", "dims": [2, 2, 2, 2]}"#),
        kinds: &["DimensionCount"],
    },
    Row {
        rule: "an array of three dimensions, the most",
        rust: "struct Gm { grid: [[[u8; 2]; 3]; 4] }",
        json: Some(r#""grid": {"type": "u8", "dims": [4, 3, 2]}"#),
        kinds: &[],
    },
    Row {
        rule: "an array of 65,536 items",
        rust: "struct Gm { big: [[u8; 256]; 256] }",
        json: Some(r#""big": {"type": "u8", "dims": [256, 256]}"#),
        kinds: &["TooManyItems"],
    },
    Row {
        rule: "an array of 65,535 items, the most",
        rust: "struct Gm { big: [u8; 65535] }",
        json: Some(r#""big": {"type": "u8", "dims": [65535]}"#),
        kinds: &[],
    },
    Row {
        rule: "an array dimension of no items",
        rust: "struct Gm { none: [u8; 0] }",
        json: Some(r#""none": {"type": "u8", "dims": [0]}"#),
        kinds: &["EmptyDimension"],
    },
    Row {
        rule: "a link to another bus",
        rust: "struct Gm { #[plc(link = \"modbus.rack1.inputs\")] inputs: u16 }",
        json: Some(r#""inputs": {"type": "u16", "link": "modbus.rack1.inputs"}"#),
        kinds: &["BadLink"],
    },
    Row {
        rule: "a link without an entry",
        rust: "struct Gm { #[plc(link = \"ethercat.el1004\")] inputs: u16 }",
        json: Some(r#""inputs": {"type": "u16", "link": "ethercat.el1004"}"#),
        kinds: &["BadLink"],
    },
    Row {
        rule: "a valid link",
        rust: "struct Gm { #[plc(link = \"ethercat.el1004_0.input1\")] inputs: bool }",
        json: Some(r#""inputs": {"type": "bool", "link": "ethercat.el1004_0.input1"}"#),
        kinds: &[],
    },
    Row {
        rule: "a link shared by two variables (a warning)",
        rust: "struct Gm { #[plc(link = \"ethercat.io.x\")] a: u8, #[plc(link = \"ethercat.io.x\")] b: u8 }",
        json: Some(r#""a": {"type": "u8", "link": "ethercat.io.x"}, "b": {"type": "u8", "link": "ethercat.io.x"}"#),
        kinds: &["SharedLink"],
    },
    Row {
        rule: "an address that does not parse",
        rust: "struct Gm { #[plc(at = \"%IWx4\")] a: i16 }",
        json: Some(r#""a": {"type": "i16", "at": "%IWx4"}"#),
        kinds: &["BadAddress"],
    },
    Row {
        rule: "an address in the M area",
        rust: "struct Gm { #[plc(at = \"%MW4\")] a: i16 }",
        json: Some(r#""a": {"type": "i16", "at": "%MW4"}"#),
        kinds: &["AddressInMemoryArea"],
    },
    Row {
        rule: "an address on an array",
        rust: "struct Gm { #[plc(at = \"%IB4\")] a: [u8; 4] }",
        json: Some(r#""a": {"type": "u8", "dims": [4], "at": "%IB4"}"#),
        kinds: &["AddressNotScalar"],
    },
    Row {
        rule: "an address on a string",
        rust: "struct Gm { #[plc(at = \"%IB4\")] a: FixedString<8> }",
        json: Some(r#""a": {"type": "string", "max_length": 8, "at": "%IB4"}"#),
        kinds: &["AddressNotScalar"],
    },
    Row {
        rule: "an address of another width than the type",
        rust: "struct Gm { #[plc(at = \"%IW4\")] force: f32 }",
        json: Some(r#""force": {"type": "f32", "at": "%IW4"}"#),
        kinds: &["AddressWidth"],
    },
    Row {
        rule: "a bit address on a byte",
        rust: "struct Gm { #[plc(at = \"%IX2.0\")] level: u8 }",
        json: Some(r#""level": {"type": "u8", "at": "%IX2.0"}"#),
        kinds: &["AddressWidth"],
    },
    Row {
        rule: "a misaligned word address",
        rust: "struct Gm { #[plc(at = \"%IW3\")] a: i16 }",
        json: Some(r#""a": {"type": "i16", "at": "%IW3"}"#),
        kinds: &["Misaligned"],
    },
    Row {
        rule: "a misaligned address allowed by `unaligned` (no such setting in a list)",
        rust: "#[plc(unaligned)] struct Gm { #[plc(at = \"%IW3\")] a: i16 }",
        json: None,
        kinds: &[],
    },
    Row {
        rule: "valid addresses of each size, aligned, side by side",
        rust: "struct Gm { #[plc(at = \"%IX0.0\")] a: bool, #[plc(at = \"%IX0.7\")] b: bool, #[plc(at = \"%IB1\")] c: u8, #[plc(at = \"%IW2\")] d: i16, #[plc(at = \"%ID4\")] e: f32, #[plc(at = \"%QL8\")] f: u64 }",
        json: Some(r#""a": {"type": "bool", "at": "%IX0.0"}, "b": {"type": "bool", "at": "%IX0.7"}, "c": {"type": "u8", "at": "%IB1"}, "d": {"type": "i16", "at": "%IW2"}, "e": {"type": "f32", "at": "%ID4"}, "f": {"type": "u64", "at": "%QL8"}"#),
        kinds: &[],
    },
    Row {
        rule: "two addresses that share a byte",
        rust: "struct Gm { #[plc(at = \"%IW4\")] analog_in: i16, #[plc(at = \"%IB5\")] high: u8 }",
        json: Some(r#""analog_in": {"type": "i16", "at": "%IW4"}, "high": {"type": "u8", "at": "%IB5"}"#),
        kinds: &["AddressOverlap"],
    },
    Row {
        rule: "an unknown direction",
        rust: "struct Gm { #[plc(direction = \"in\")] a: u8 }",
        json: Some(r#""a": {"type": "u8", "direction": "in"}"#),
        kinds: &["UnknownDirection"],
    },
    Row {
        rule: "a direction that contradicts the address",
        rust: "struct Gm { #[plc(at = \"%IW4\", direction = \"output\")] analog_in: i16 }",
        json: Some(r#""analog_in": {"type": "i16", "at": "%IW4", "direction": "output"}"#),
        kinds: &["DirectionContradictsAddress"],
    },
    Row {
        rule: "a bit-mapped bool whose direction contradicts its source's",
        rust: "struct Gm { #[plc(direction = \"input\")] inputs: u16, #[plc(source = \"inputs\", bit = 0, direction = \"output\")] b: bool }",
        json: Some(r#""inputs": {"type": "u16", "direction": "input"}, "b": {"type": "bool", "source": "inputs", "bit": 0, "direction": "output"}"#),
        kinds: &["DirectionContradictsSource"],
    },
    Row {
        rule: "a bit-mapped bool that agrees with its source's direction",
        rust: "struct Gm { #[plc(at = \"%IW0\")] inputs: u16, #[plc(source = \"inputs\", bit = 0, direction = \"input\")] b: bool }",
        json: Some(r#""inputs": {"type": "u16", "at": "%IW0"}, "b": {"type": "bool", "source": "inputs", "bit": 0, "direction": "input"}"#),
        kinds: &[],
    },
    Row {
        rule: "a source without a bit",
        rust: "struct Gm { w: u16, #[plc(source = \"w\")] b: bool }",
        json: Some(r#""w": {"type": "u16"}, "b": {"type": "bool", "source": "w"}"#),
        kinds: &["SourceWithoutBit"],
    },
    Row {
        rule: "a bit without a source",
        rust: "struct Gm { w: u16, #[plc(bit = 1)] b: bool }",
        json: Some(r#""w": {"type": "u16"}, "b": {"type": "bool", "bit": 1}"#),
        kinds: &["BitWithoutSource"],
    },
    Row {
        rule: "bit 64",
        rust: "struct Gm { w: u64, #[plc(source = \"w\", bit = 64)] b: bool }",
        json: Some(r#""w": {"type": "u64"}, "b": {"type": "bool", "source": "w", "bit": 64}"#),
        kinds: &["BadBit"],
    },
    Row {
        rule: "a negative bit",
        rust: "struct Gm { w: u64, #[plc(source = \"w\", bit = -1)] b: bool }",
        json: Some(r#""w": {"type": "u64"}, "b": {"type": "bool", "source": "w", "bit": -1}"#),
        kinds: &["BadBit"],
    },
    Row {
        rule: "bits 0 and 63 of a u64, the limits",
        rust: "struct Gm { w: u64, #[plc(source = \"w\", bit = 0)] lo: bool, #[plc(source = \"w\", bit = 63)] hi: bool }",
        json: Some(r#""w": {"type": "u64"}, "lo": {"type": "bool", "source": "w", "bit": 0}, "hi": {"type": "bool", "source": "w", "bit": 63}"#),
        kinds: &[],
    },
    Row {
        rule: "a bit-mapped variable that is not a bool",
        rust: "struct Gm { w: u16, #[plc(source = \"w\", bit = 3)] level: u8 }",
        json: Some(r#""w": {"type": "u16"}, "level": {"type": "u8", "source": "w", "bit": 3}"#),
        kinds: &["MappedNotBool"],
    },
    Row {
        rule: "a bool that is its own source",
        rust: "struct Gm { #[plc(source = \"flag\", bit = 1)] flag: bool }",
        json: Some(r#""flag": {"type": "bool", "source": "flag", "bit": 1}"#),
        kinds: &["SourceIsSelf"],
    },
    Row {
        rule: "a source that names no variable",
        rust: "struct Gm { #[plc(source = \"nope\", bit = 1)] b: bool }",
        json: Some(r#""b": {"type": "bool", "source": "nope", "bit": 1}"#),
        kinds: &["SourceUnknown"],
    },
    Row {
        rule: "a source that is a real",
        rust: "struct Gm { force: f32, #[plc(source = \"force\", bit = 1)] b: bool }",
        json: Some(r#""force": {"type": "f32"}, "b": {"type": "bool", "source": "force", "bit": 1}"#),
        kinds: &["SourceNotInteger"],
    },
    Row {
        rule: "a source that is an array",
        rust: "struct Gm { words: [u16; 2], #[plc(source = \"words\", bit = 1)] b: bool }",
        json: Some(r#""words": {"type": "u16", "dims": [2]}, "b": {"type": "bool", "source": "words", "bit": 1}"#),
        kinds: &["SourceNotInteger"],
    },
    Row {
        rule: "a bit beyond the source's width",
        rust: "struct Gm { impact67_0_digital_inputs: u16, #[plc(source = \"impact67_0_digital_inputs\", bit = 16)] ls_lift_neg: bool }",
        json: Some(r#""impact67_0_digital_inputs": {"type": "u16"}, "ls_lift_neg": {"type": "bool", "source": "impact67_0_digital_inputs", "bit": 16}"#),
        kinds: &["BitOutOfRange"],
    },
    Row {
        rule: "two bools on one bit",
        rust: "struct Gm { w: u16, #[plc(source = \"w\", bit = 1)] a: bool, #[plc(source = \"w\", bit = 1)] b: bool }",
        json: Some(r#""w": {"type": "u16"}, "a": {"type": "bool", "source": "w", "bit": 1}, "b": {"type": "bool", "source": "w", "bit": 1}"#),
        kinds: &["BitTaken"],
    },
    Row {
        rule: "a number as the initial value of a bool",
        rust: "struct Gm { #[plc(initial = 1)] enabled: bool }",
        json: Some(r#""enabled": {"type": "bool", "initial": 1}"#),
        kinds: &["InitialWrongKind"],
    },
    Row {
        rule: "a real as the initial value of an integer",
        rust: "struct Gm { #[plc(initial = 2.5)] count: u16 }",
        json: Some(r#""count": {"type": "u16", "initial": 2.5}"#),
        kinds: &["InitialWrongKind"],
    },
    Row {
        rule: "a number as the initial value of a string",
        rust: "struct Gm { #[plc(initial = 7)] label: FixedString<8> }",
        json: Some(r#""label": {"type": "string", "max_length": 8, "initial": 7}"#),
        kinds: &["InitialWrongKind"],
    },
    Row {
        rule: "text as the initial value of an integer",
        rust: "struct Gm { #[plc(initial = \"fast\")] speed: i32 }",
        json: Some(r#""speed": {"type": "i32", "initial": "fast"}"#),
        kinds: &["InitialWrongKind"],
    },
    Row {
        rule: "an initial value beyond the type's range",
        rust: "struct Gm { #[plc(initial = 256)] level: u8 }",
        json: Some(r#""level": {"type": "u8", "initial": 256}"#),
        kinds: &["InitialOutOfRange"],
    },
    Row {
        rule: "a negative initial value of an unsigned type",
        rust: "struct Gm { #[plc(initial = -1)] count: u32 }",
        json: Some(r#""count": {"type": "u32", "initial": -1}"#),
        kinds: &["InitialOutOfRange"],
    },
    Row {
        rule: "an initial real beyond REAL",
        rust: "struct Gm { #[plc(initial = 1e39)] force: f32 }",
        json: Some(r#""force": {"type": "f32", "initial": 1e39}"#),
        kinds: &["InitialOutOfRange"],
    },
    Row {
        rule: "initial values at the limits of their types, a bare integer for a REAL",
        rust: "struct Gm { #[plc(initial = -128)] a: i8, #[plc(initial = 127)] b: i8, #[plc(initial = 18446744073709551615)] c: u64, #[plc(initial = 3)] d: f32, #[plc(initial = -0.5)] e: f64, #[plc(initial = true)] f: bool }",
        json: Some(r#""a": {"type": "i8", "initial": -128}, "b": {"type": "i8", "initial": 127}, "c": {"type": "u64", "initial": 18446744073709551615}, "d": {"type": "f32", "initial": 3}, "e": {"type": "f64", "initial": -0.5}, "f": {"type": "bool", "initial": true}"#),
        kinds: &[],
    },
    Row {
        rule: "durations (LTIME) with initial literals of each prefix, a sign, a fraction",
        rust: "struct Gm { #[plc(initial = \"T#1s500ms\")] a: Time, #[plc(initial = \"LTIME#-2h_30m\")] b: plc_core::Time, #[plc(initial = \"lt#1.5s\")] c: Time, d: [Time; 2] }",
        json: Some(r#""a": {"type": "LTIME", "initial": "T#1s500ms"}, "b": {"type": "LTIME", "initial": "LTIME#-2h_30m"}, "c": {"type": "ltime", "initial": "lt#1.5s"}, "d": {"type": "LTIME", "dims": [2]}"#),
        kinds: &[],
    },
    Row {
        rule: "a duration literal whose later part reaches the next unit",
        rust: "struct Gm { #[plc(initial = \"T#1h75m\")] delay: Time }",
        json: Some(r#""delay": {"type": "LTIME", "initial": "T#1h75m"}"#),
        kinds: &["InitialBadTime"],
    },
    Row {
        rule: "a duration literal with its units out of order",
        rust: "struct Gm { #[plc(initial = \"T#5s1m\")] delay: Time }",
        json: Some(r#""delay": {"type": "LTIME", "initial": "T#5s1m"}"#),
        kinds: &["InitialBadTime"],
    },
    Row {
        rule: "a duration beyond LTIME",
        rust: "struct Gm { #[plc(initial = \"T#106752d\")] delay: Time }",
        json: Some(r#""delay": {"type": "LTIME", "initial": "T#106752d"}"#),
        kinds: &["InitialOutOfRange"],
    },
    Row {
        rule: "a bare number as the initial value of a duration (its unit would be a guess)",
        rust: "struct Gm { #[plc(initial = 5000)] delay: Time }",
        json: Some(r#""delay": {"type": "LTIME", "initial": 5000}"#),
        kinds: &["InitialWrongKind"],
    },
    Row {
        rule: "initial text longer than the string",
        rust: "struct Gm { #[plc(initial = \"TEST-0001\")] test_id: FixedString<8> }",
        json: Some(r#""test_id": {"type": "string", "max_length": 8, "initial": "TEST-0001"}"#),
        kinds: &["InitialTooLong"],
    },
    Row {
        rule: "initial text exactly as long as the string",
        rust: "struct Gm { #[plc(initial = \"TEST-001\")] test_id: FixedString<8> }",
        json: Some(r#""test_id": {"type": "string", "max_length": 8, "initial": "TEST-001"}"#),
        kinds: &[],
    },
    Row {
        rule: "a bit-string type of another width (a list declares the type itself)",
        rust: "struct Gm { #[plc(iec_type = \"WORD\")] flags: u32 }",
        json: None,
        kinds: &["IecTypeMismatch"],
    },
    Row {
        rule: "a bit-string type of the same width",
        rust: "struct Gm { #[plc(iec_type = \"WORD\")] flags: u16 }",
        json: Some(r#""flags": {"type": "WORD"}"#),
        kinds: &[],
    },
    Row {
        rule: "a bool mapped onto an alias (a list has no aliases: the compiler checks it)",
        rust: "struct Gm { w: Word, #[plc(source = \"w\", bit = 3)] b: bool }",
        json: None,
        kinds: &[],
    },
    Row {
        rule: "a generic struct (no list form: the derive refuses it on its own)",
        rust: "struct Gm<T> { w: T }",
        json: None,
        kinds: &[],
    },
    Row {
        rule: "a link and an address inside a structure",
        rust: "#[derive(PlcStruct)] struct Axis { #[plc(link = \"ethercat.io.x\")] a: u16, #[plc(at = \"%IW4\")] b: i16 }",
        json: Some(r#""a": {"type": "u16", "link": "ethercat.io.x"}, "b": {"type": "i16", "at": "%IW4"}"#),
        kinds: &["IoInStructure", "IoInStructure"],
    },
    Row {
        rule: "IN and OUT parameters and an internal member of a structure",
        rust: "#[derive(PlcStruct)] struct Axis { #[plc(direction = \"input\")] a: bool, #[plc(direction = \"output\")] b: bool, c: u8 }",
        json: Some(r#""a": {"type": "bool", "direction": "input"}, "b": {"type": "bool", "direction": "output"}, "c": {"type": "u8"}"#),
        kinds: &[],
    },
    Row {
        rule: "a command and a status inside a structure",
        rust: "#[derive(PlcStruct)] struct Axis { #[plc(direction = \"command\")] a: bool, #[plc(direction = \"status\")] b: bool }",
        json: Some(r#""a": {"type": "bool", "direction": "command"}, "b": {"type": "bool", "direction": "status"}"#),
        kinds: &["DirectionInStructure", "DirectionInStructure"],
    },
    Row {
        rule: "a name given twice within a structure, in another case",
        rust: "#[derive(PlcStruct)] struct Axis { pos: f64, #[plc(name = \"POS\")] pos_2: f64 }",
        json: Some(r#""pos": {"type": "f64"}, "POS": {"type": "f64"}"#),
        kinds: &["DuplicateName"],
    },
    Row {
        rule: "a bool mapped onto a member of the same structure, and an initial out of range there",
        rust: "#[derive(PlcStruct)] struct Axis { state: u8, #[plc(source = \"state\", bit = 8)] homed: bool, #[plc(initial = 300)] count: u8 }",
        json: Some(r#""state": {"type": "u8"}, "homed": {"type": "bool", "source": "state", "bit": 8}, "count": {"type": "u8", "initial": 300}"#),
        kinds: &["BitOutOfRange", "InitialOutOfRange"],
    },
    Row {
        rule: "alarms on a bool, an active-low bool, an array of bools and a number with every option",
        rust: "struct Gm { #[plc(alarm = \"Guard door open\")] door: bool, #[plc(alarm = \"Air pressure low\", alarm_when = false)] air_ok: bool, #[plc(alarm(text = \"Overtravel\", severity = 1000, latched))] limits: [bool; 2], #[plc(alarm(text = \"Oil temperature\", high = 80.0, high_high = 95.0, low = 5, low_low = -10.5, deadband = 1.0, delay = \"2s\", severity = 1, latched, suppress_when = \"pump_off\"))] oil: f32, pump_off: bool }",
        json: Some(r#""door": {"type": "bool", "alarm": "Guard door open"}, "air_ok": {"type": "bool", "alarm": {"text": "Air pressure low", "alarm_when": false}}, "limits": {"type": "bool", "dims": [2], "alarm": {"text": "Overtravel", "severity": 1000, "latched": true}}, "oil": {"type": "f32", "alarm": {"text": "Oil temperature", "high": 80.0, "high_high": 95.0, "low": 5, "low_low": -10.5, "deadband": 1.0, "delay": "2s", "severity": 1, "latched": true, "suppress_when": "pump_off"}}, "pump_off": {"type": "bool"}"#),
        kinds: &[],
    },
    Row {
        rule: "limits that meet where the standard allows it (low_low = low, high = high_high), a delay written as an IEC literal",
        rust: "struct Gm { #[plc(alarm(text = \"Level\", low_low = 2, low = 2, high = 9, high_high = 9, delay = \"T#1m30s\"))] level: i16 }",
        json: Some(r#""level": {"type": "i16", "alarm": {"text": "Level", "low_low": 2, "low": 2, "high": 9, "high_high": 9, "delay": "T#1m30s"}}"#),
        kinds: &[],
    },
    Row {
        rule: "an alarm on a STRING and on a duration",
        rust: "struct Gm { #[plc(alarm = \"Bad id\")] id: FixedString<8>, #[plc(alarm = \"Slow\")] cycle: Time }",
        json: Some(r#""id": {"type": "string", "max_length": 8, "alarm": "Bad id"}, "cycle": {"type": "LTIME", "alarm": "Slow"}"#),
        kinds: &["AlarmOnType", "AlarmOnType"],
    },
    Row {
        rule: "limits and a deadband on a bool",
        rust: "struct Gm { #[plc(alarm(text = \"Door\", high = 1.0, deadband = 0.5))] door: bool }",
        json: Some(r#""door": {"type": "bool", "alarm": {"text": "Door", "high": 1.0, "deadband": 0.5}}"#),
        kinds: &["AlarmLimitOnBool", "AlarmLimitOnBool"],
    },
    Row {
        rule: "alarm_when on a number, and a number without limits",
        rust: "struct Gm { #[plc(alarm = \"Speed\", alarm_when = false)] speed: i32, #[plc(alarm = \"Force\")] force: f64 }",
        json: Some(r#""speed": {"type": "i32", "alarm": {"text": "Speed", "alarm_when": false}}, "force": {"type": "f64", "alarm": "Force"}"#),
        kinds: &["AlarmWhenOnNumber", "AlarmWithoutLimits", "AlarmWithoutLimits"],
    },
    Row {
        rule: "limits out of order: high below low, high_high below high, low equal to high",
        rust: "struct Gm { #[plc(alarm(text = \"T\", low = 90.0, high = 80.0))] a: f32, #[plc(alarm(text = \"T\", high = 80.0, high_high = 70.0))] b: f32, #[plc(alarm(text = \"T\", low = 5, high = 5))] c: u16 }",
        json: Some(r#""a": {"type": "f32", "alarm": {"text": "T", "low": 90.0, "high": 80.0}}, "b": {"type": "f32", "alarm": {"text": "T", "high": 80.0, "high_high": 70.0}}, "c": {"type": "u16", "alarm": {"text": "T", "low": 5, "high": 5}}"#),
        kinds: &["AlarmLimitOrder", "AlarmLimitOrder", "AlarmLimitOrder"],
    },
    Row {
        rule: "a negative deadband, a bad and a negative delay, severities 0 and 1001, empty text",
        rust: "struct Gm { #[plc(alarm(text = \"T\", high = 1, deadband = -0.5))] a: f32, #[plc(alarm(text = \"T\", delay = \"soon\"))] b: bool, #[plc(alarm(text = \"T\", delay = \"-1s\"))] c: bool, #[plc(alarm(text = \"T\", severity = 0))] d: bool, #[plc(alarm(text = \"T\", severity = 1001))] e: bool, #[plc(alarm = \" \")] f: bool }",
        json: Some(r#""a": {"type": "f32", "alarm": {"text": "T", "high": 1, "deadband": -0.5}}, "b": {"type": "bool", "alarm": {"text": "T", "delay": "soon"}}, "c": {"type": "bool", "alarm": {"text": "T", "delay": "-1s"}}, "d": {"type": "bool", "alarm": {"text": "T", "severity": 0}}, "e": {"type": "bool", "alarm": {"text": "T", "severity": 1001}}, "f": {"type": "bool", "alarm": " "}"#),
        kinds: &["AlarmNegativeDeadband", "AlarmBadDelay", "AlarmBadDelay", "AlarmSeverity", "AlarmSeverity", "AlarmEmptyText"],
    },
    Row {
        rule: "suppress_when naming no variable, and a variable that is not a bool",
        rust: "struct Gm { #[plc(alarm(text = \"T\", suppress_when = \"pump_offf\"))] a: bool, #[plc(alarm(text = \"T\", suppress_when = \"mode\"))] b: bool, mode: u8, pump_off: bool }",
        json: Some(r#""a": {"type": "bool", "alarm": {"text": "T", "suppress_when": "pump_offf"}}, "b": {"type": "bool", "alarm": {"text": "T", "suppress_when": "mode"}}, "mode": {"type": "u8"}, "pump_off": {"type": "bool"}"#),
        kinds: &["AlarmSuppressUnknown", "AlarmSuppressNotBool"],
    },
    Row {
        rule: "suppress_when naming an element of a bool array (fine), one beyond it, the whole array, and into a basic variable",
        rust: "struct Gm { #[plc(alarm(text = \"A\", suppress_when = \"off[1]\"))] a: bool, #[plc(alarm(text = \"B\", suppress_when = \"off[2]\"))] b: bool, #[plc(alarm(text = \"C\", suppress_when = \"off\"))] c: bool, #[plc(alarm(text = \"D\", suppress_when = \"mode.x\"))] d: bool, off: [bool; 2], mode: bool }",
        json: Some(r#""a": {"type": "bool", "alarm": {"text": "A", "suppress_when": "off[1]"}}, "b": {"type": "bool", "alarm": {"text": "B", "suppress_when": "off[2]"}}, "c": {"type": "bool", "alarm": {"text": "C", "suppress_when": "off"}}, "d": {"type": "bool", "alarm": {"text": "D", "suppress_when": "mode.x"}}, "off": {"type": "bool", "dims": [2]}, "mode": {"type": "bool"}"#),
        kinds: &["AlarmSuppressUnknown", "AlarmSuppressNotBool", "AlarmSuppressNotBool"],
    },
    Row {
        rule: "alarms on a structure's members, suppressed by a member of the same structure; a path beyond the structure refused",
        rust: "#[derive(PlcStruct)] struct Station { #[plc(alarm(text = \"Door open\", suppress_when = \"out_of_service\"))] door: bool, out_of_service: bool, #[plc(alarm(text = \"Jam\", suppress_when = \"cell.off\"))] jam: bool }",
        json: Some(r#""door": {"type": "bool", "alarm": {"text": "Door open", "suppress_when": "out_of_service"}}, "out_of_service": {"type": "bool"}, "jam": {"type": "bool", "alarm": {"text": "Jam", "suppress_when": "cell.off"}}"#),
        kinds: &["AlarmSuppressUnknown"],
    },
    Row {
        rule: "units and reporting deadbands on integers, reals and arrays of them, beside an alarm's own deadband",
        rust: "struct Gm { #[plc(unit = \"kN\", deadband = 0.5)] force: f32, #[plc(unit = \"mm\", deadband = 0)] pos: [f64; 3], #[plc(unit = \"1/min\", deadband = 2)] speed: i32, #[plc(unit = \"°C\", deadband = 1.0, alarm(text = \"Hot\", high = 80.0, deadband = 2.0))] temp: f32 }",
        json: Some(r#""force": {"type": "f32", "unit": "kN", "deadband": 0.5}, "pos": {"type": "f64", "dims": [3], "unit": "mm", "deadband": 0}, "speed": {"type": "i32", "unit": "1/min", "deadband": 2}, "temp": {"type": "f32", "unit": "°C", "deadband": 1.0, "alarm": {"text": "Hot", "high": 80.0, "deadband": 2.0}}"#),
        kinds: &[],
    },
    Row {
        rule: "a unit on a bool, a STRING, a duration and a bit string",
        rust: "struct Gm { #[plc(unit = \"mm\")] a: bool, #[plc(unit = \"mm\")] b: FixedString<8>, #[plc(unit = \"s\")] c: Time, #[plc(unit = \"mm\", iec_type = \"WORD\")] d: u16 }",
        json: Some(r#""a": {"type": "bool", "unit": "mm"}, "b": {"type": "string", "max_length": 8, "unit": "mm"}, "c": {"type": "LTIME", "unit": "s"}, "d": {"type": "WORD", "unit": "mm"}"#),
        kinds: &["UnitOnType", "UnitOnType", "UnitOnType", "UnitOnType"],
    },
    Row {
        rule: "an empty unit, one of 33 characters and one with a tab",
        rust: "struct Gm { #[plc(unit = \"\")] a: f32, #[plc(unit = \"mmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmm\")] b: f32, #[plc(unit = \"m\\tm\")] c: f32 }",
        json: Some(r#""a": {"type": "f32", "unit": ""}, "b": {"type": "f32", "unit": "mmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmmm"}, "c": {"type": "f32", "unit": "m\tm"}"#),
        kinds: &["BadUnit", "BadUnit", "BadUnit"],
    },
    Row {
        rule: "a negative reporting deadband, and one on a bool, a STRING and a duration",
        rust: "struct Gm { #[plc(deadband = -0.5)] a: f32, #[plc(deadband = 1)] b: bool, #[plc(deadband = 1)] c: FixedString<8>, #[plc(deadband = 1)] d: Time }",
        json: Some(r#""a": {"type": "f32", "deadband": -0.5}, "b": {"type": "bool", "deadband": 1}, "c": {"type": "string", "max_length": 8, "deadband": 1}, "d": {"type": "LTIME", "deadband": 1}"#),
        kinds: &["NegativeDeadband", "DeadbandOnType", "DeadbandOnType", "DeadbandOnType"],
    },
    Row {
        rule: "a unit and a deadband on a structure's members, and a unit on its bool",
        rust: "#[derive(PlcStruct)] struct Axis { #[plc(unit = \"mm\", deadband = 0.01)] pos: f64, #[plc(unit = \"mm\")] homed: bool }",
        json: Some(r#""pos": {"type": "f64", "unit": "mm", "deadband": 0.01}, "homed": {"type": "bool", "unit": "mm"}"#),
        kinds: &["UnitOnType"],
    },
    Row {
        rule: "every mistake of a declaration at once",
        rust: "struct Gm { #[plc(initial = 300)] a: u8, ton: bool, #[plc(link = \"ethercat.io\")] c: u8, #[plc(at = \"%IW3\")] d: i16 }",
        json: Some(r#""a": {"type": "u8", "initial": 300}, "ton": {"type": "bool"}, "c": {"type": "u8", "link": "ethercat.io"}, "d": {"type": "i16", "at": "%IW3"}"#),
        kinds: &["InitialOutOfRange", "BadName", "BadLink", "Misaligned"],
    },
];

/// `kinds` sorted, for comparison in any order.
fn sorted(kinds: impl IntoIterator<Item = &'static str>) -> Vec<&'static str> {
    let mut v: Vec<&'static str> = kinds.into_iter().collect();
    v.sort_unstable();
    v
}
