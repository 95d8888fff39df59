//! Alarms in variable lists: a JSON `"alarm"` and the CSV alarm columns give the derive's
//! `alarm(...)` attribute, and their mistakes are worded as the derive words them, at the
//! variable and the alarm's key (JSON) or column (CSV).
#![cfg(feature = "import")]

#[path = "common/json_lists.rs"]
mod json_lists;

use json_lists::{errors, vars};
use plc_io::import::{ALARM_COLUMNS, COLUMNS, ImportErrors, Options, generate, generate_csv};

#[test]
fn a_json_alarm_becomes_the_derives_attribute() {
    let json = vars(
        r#""door": { "type": "bool", "alarm": "Guard door open" },
        "air_ok": { "type": "bool", "alarm": { "text": "Air pressure low", "alarm_when": false } },
        "oil": { "type": "f32", "alarm": { "text": "Oil temperature", "high": 80, "high_high": 95.5,
                 "low": -5, "deadband": 1.0, "delay": "2s", "severity": 600, "latched": true,
                 "suppress_when": "pump_off" } },
        "pump_off": { "type": "bool" }"#,
    );
    let code = generate(&json, &Options::default()).unwrap().code;
    assert!(
        code.contains(r#"#[plc(alarm = "Guard door open", "#),
        "{code}"
    );
    assert!(
        code.contains(r#"alarm(text = "Air pressure low", alarm_when = false)"#),
        "{code}"
    );
    // A long attribute is spread over lines by the formatter.
    let flat: String = code.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        flat.contains(
            r#"alarm( text = "Oil temperature", high = 80.0, high_high = 95.5, low = -5.0, deadband = 1.0, delay = "2s", severity = 600, latched, suppress_when = "pump_off" )"#
        ),
        "{flat}"
    );
}

#[test]
fn json_alarm_mistakes_name_the_variable_and_the_alarms_key() {
    let e = errors(&vars(
        r#""oil": { "type": "f32", "alarm": { "text": "Oil", "low": 90, "high": 80, "severity": 0 } },
        "id": { "type": "string", "alarm": "Bad id" },
        "door": { "type": "bool", "alarm": { "text": "Door", "delay": 2, "colour": "red" } },
        "air": { "type": "bool", "alarm": { "severity": 5 } },
        "fan": { "type": "bool", "alarm": 5 }"#,
    ));
    let expected = [
        "variables.oil.alarm.high: `high = 80` must be above `low = 90`",
        "variables.oil.alarm.severity: severity 0 is out of range: an alarm's severity is 1..=1000",
        "variables.id.alarm: no alarm can be declared on FixedString<64> (STRING)",
        "variables.door.alarm.delay: expected a string, found 2",
        "variables.door.alarm.colour: unknown field of an alarm: use one of text, severity",
        "variables.air.alarm: an alarm needs \"text\"",
        "variables.fan.alarm: expected the alarm's text",
    ];
    for x in expected {
        assert!(e.iter().any(|m| m.starts_with(x)), "{x}\nin {e:#?}");
    }
    assert_eq!(e.len(), expected.len(), "{e:#?}");
}

#[test]
fn an_alarm_on_a_structure_as_a_whole_is_refused_and_on_its_members_kept() {
    let json = r#"{
        "types": { "Station": { "variables": {
            "door": { "type": "bool", "alarm": { "text": "Door open", "suppress_when": "off" } },
            "off": { "type": "bool" } } } },
        "variables": { "stations": { "type": "Station", "dims": [3] },
                       "cell": { "type": "Station", "alarm": "Cell" } } }"#;
    let e = match generate(json, &Options::default()) {
        Err(ImportErrors(e)) => e,
        Ok(g) => panic!("{}", g.code),
    };
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(
        e[0].starts_with(
            "variables.cell.alarm: \"cell\" is a structure: declare alarms on its members"
        ),
        "{e:?}"
    );
    let ok = json.replace(r#", "alarm": "Cell""#, "");
    let code = generate(&ok, &Options::default()).unwrap().code;
    assert!(
        code.contains(r#"alarm(text = "Door open", suppress_when = "off")"#),
        "{code}"
    );
}

fn header() -> String {
    COLUMNS
        .iter()
        .chain(&[
            "alarm",
            "alarm_high",
            "alarm_deadband",
            "alarm_latched",
            "alarm_when",
        ])
        .copied()
        .collect::<Vec<_>>()
        .join(",")
}

#[test]
fn csv_alarm_columns_give_the_same_code_as_the_same_json() {
    let empty = ",".repeat(COLUMNS.len() - 2);
    let csv = format!(
        "{}\r\ndoor,bool{empty},Guard door open,,,,\r\nair_ok,bool{empty},Air pressure low,,,,FALSE\r\noil,f32{empty},Oil temperature,80,1.5,TRUE,\r\n",
        header()
    );
    let json = vars(
        r#""door": { "type": "bool", "alarm": "Guard door open" },
        "air_ok": { "type": "bool", "alarm": { "text": "Air pressure low", "alarm_when": false } },
        "oil": { "type": "f32", "alarm": { "text": "Oil temperature", "high": 80, "deadband": 1.5, "latched": true } }"#,
    );
    let o = Options::default();
    assert_eq!(
        generate_csv(&csv, &o).unwrap().code,
        generate(&json, &o).unwrap().code
    );
    assert_eq!(ALARM_COLUMNS[0], "alarm");
}

#[test]
fn csv_alarm_mistakes_name_the_line_and_the_column() {
    let empty = ",".repeat(COLUMNS.len() - 2);
    let csv = format!(
        "{}\r\ndoor,bool{empty},Door,1,,,\r\noil,f32{empty},Oil,80,-1,,\r\nfan,bool{empty},,,,yes,\r\n",
        header()
    );
    let e = match generate_csv(&csv, &Options::default()) {
        Err(ImportErrors(e)) => e,
        Ok(g) => panic!("{}", g.code),
    };
    let expected = [
        "line 2, variable door, column alarm_high: `high` is for alarms on numbers",
        "line 3, variable oil, column alarm_deadband: deadband -1 is negative",
        "line 4, variable fan, column alarm_latched: expected true or false, found \"yes\"",
        "line 4, variable fan, column alarm: an alarm needs \"text\"",
    ];
    for x in expected {
        assert!(e.iter().any(|m| m.starts_with(x)), "{x}\nin {e:#?}");
    }
    assert_eq!(e.len(), expected.len(), "{e:#?}");
}

#[cfg(feature = "export")]
#[test]
fn a_compiled_types_alarms_export_as_json_and_csv_and_import_back() {
    use plc_core::{GlobalMemory, PlcStruct};
    use plc_io::import::{export_csv, export_json};

    #[derive(PlcStruct, Debug, Clone)]
    struct Station {
        #[plc(alarm(text = "Door open", suppress_when = "off", latched))]
        door: bool,
        off: bool,
    }
    #[derive(GlobalMemory, Debug, Clone)]
    struct Gm {
        #[plc(alarm = "Guard door open")]
        door: bool,
        #[plc(alarm = "Air pressure low", alarm_when = false)]
        air: bool,
        #[plc(alarm(
            text = "Oil",
            high = 80,
            deadband = 1.5,
            delay = "1.5s",
            severity = 600
        ))]
        oil: f32,
        #[plc(alarm(text = "Jam", suppress_when = "door"))]
        jam: [bool; 2],
        stations: [Station; 2],
    }
    let json = export_json::<Gm>().unwrap();
    let list: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(list["variables"]["door"]["alarm"], "Guard door open");
    assert_eq!(list["variables"]["air"]["alarm"]["alarm_when"], false);
    assert_eq!(list["variables"]["oil"]["alarm"]["delay"], "LTIME#1s500ms");
    assert_eq!(list["variables"]["jam"]["alarm"]["suppress_when"], "door");
    let door = &list["types"]["Station"]["variables"]["door"]["alarm"];
    assert_eq!(
        (&door["suppress_when"], &door["latched"]),
        (&"off".into(), &true.into())
    );
    let o = Options::default();
    let code = generate(&json, &o).unwrap().code;
    let flat: String = code.split_whitespace().collect::<Vec<_>>().join(" ");
    for attr in [
        r#"alarm = "Guard door open""#,
        r#"alarm(text = "Air pressure low", alarm_when = false)"#,
        r#"alarm( text = "Oil", high = 80.0, deadband = 1.5, delay = "LTIME#1s500ms", severity = 600 )"#,
        r#"alarm(text = "Jam", suppress_when = "door")"#,
        r#"alarm(text = "Door open", latched, suppress_when = "off")"#,
    ] {
        assert!(flat.contains(attr), "{attr}\nin {flat}");
    }
    let csv = export_csv::<Gm>().unwrap();
    assert!(csv.starts_with(&format!(
        "{},{}",
        COLUMNS.join(","),
        ALARM_COLUMNS.join(",")
    )));
    assert_eq!(generate_csv(&csv, &o).unwrap().code, code);
}
