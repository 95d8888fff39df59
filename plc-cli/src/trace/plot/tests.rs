//! The picture read back as XML: its lines, texts and sizes.

use super::*;
use plc_core::Value;

fn column(path: &str, iec_type: IecType, unit: Option<&str>) -> Column {
    Column {
        path: path.into(),
        iec_type,
        unit: unit.map(str::to_string),
    }
}

/// A tensile test at `hz` for `seconds`, time zero at 1 s: force (kN), position (mm), two
/// bools.
fn tensile(hz: u64, seconds: u64) -> (Vec<Column>, Vec<Row>) {
    let columns = vec![
        column("force_kn", IecType::Real, Some("kN")),
        column("axes[1].position", IecType::Lreal, Some("mm")),
        column("clamp_closed", IecType::Bool, None),
        column("ls_upper", IecType::Bool, None),
    ];
    let rows = (0..hz * seconds)
        .map(|i| {
            let t = i as f64 / hz as f64 - 1.0;
            let force = if t < 0.0 {
                0.2 * (40.0 * t).sin()
            } else {
                45.0 * (1.0 - (-3.0 * t).exp()) + 3.0 * (9.0 * t).sin()
            };
            Row {
                cycle: i,
                time_ns: i * 1_000_000_000 / hz,
                values: vec![
                    Value::Real(force as f32 as f64),
                    Value::Real(10.0 + 8.0 * t.max(0.0)),
                    Value::Bool(t > -0.5),
                    Value::Bool((t * 2.0).rem_euclid(1.0) < 0.3 && t > 0.0),
                ],
            }
        })
        .collect();
    (columns, rows)
}

/// Texts, and the stroke colours of polylines with their point counts, of an SVG.
fn parts(svg: &str) -> (Vec<String>, Vec<(String, usize)>) {
    let doc = roxmltree::Document::parse(svg).expect("the SVG is XML");
    let texts = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(|t| t.trim().to_string()))
        .collect();
    let lines = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .map(|n| {
            let points = n
                .attribute("points")
                .unwrap_or("")
                .split_whitespace()
                .count();
            (
                n.attribute("stroke").unwrap_or("").to_ascii_lowercase(),
                points,
            )
        })
        .collect();
    (texts, lines)
}

/// The texts of the picture of `rows` of `columns`, without a trigger.
fn texts_of(columns: &[Column], rows: &[Row]) -> Vec<String> {
    let samples = Samples::from_rows(columns.len(), rows);
    parts(&svg("t", columns, &samples, None).unwrap()).0
}

fn hex(c: RGBColor) -> String {
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

#[test]
fn draws_a_line_per_variable_a_legend_with_units_and_the_trigger() {
    let (columns, rows) = tensile(1000, 3);
    let svg = svg(
        "tensile_tester",
        &columns,
        &Samples::from_rows(columns.len(), &rows),
        Some(1_000_000_000),
    )
    .unwrap();
    let (texts, lines) = parts(&svg);
    for want in [
        "tensile_tester",
        "force_kn (kN)",
        "axes[1].position (mm)",
        "clamp_closed",
        "ls_upper",
        "trigger",
        "time from trigger (s)",
        "kN, mm",
    ] {
        assert!(
            texts.iter().any(|t| t == want),
            "no text {want:?} in {texts:?}"
        );
    }
    for color in [PALETTE[0], PALETTE[1]] {
        assert!(
            lines.iter().any(|(s, n)| *s == hex(color) && *n > 100),
            "{color:?}"
        );
    }
    let bool_lines = lines
        .iter()
        .filter(|(s, n)| *s == hex(BOOL_COLOR) && *n > 2);
    assert_eq!(bool_lines.count(), 2);
}

#[test]
fn ranges_far_apart_get_panels_of_their_own() {
    let columns = [
        column("force", IecType::Lreal, Some("kN")),
        column("strain", IecType::Lreal, Some("%")),
        column("load", IecType::Lreal, Some("kN")),
    ];
    let rows: Vec<Row> = (0..100u64)
        .map(|i| Row {
            cycle: i,
            time_ns: i * 1_000_000,
            values: [50.0, 0.01, 30.0]
                .map(|a| Value::Real(a * (i as f64 / 10.0).sin()))
                .to_vec(),
        })
        .collect();
    let texts = texts_of(&columns, &rows);
    assert!(
        texts.iter().any(|t| t == "kN") && texts.iter().any(|t| t == "%"),
        "{texts:?}"
    );
    assert!(texts.iter().any(|t| t == "time from first row (s)"));
}

#[test]
fn a_value_without_a_unit_never_shares_an_axis_that_names_one() {
    // A running timer (seconds) and a counter of about the same range: one panel by range,
    // but the counter is no number of seconds.
    let columns = [
        column("timer.ET", IecType::Ltime, None),
        column("parts", IecType::Dint, None),
    ];
    let rows: Vec<Row> = (0..100u64)
        .map(|i| Row {
            cycle: i,
            time_ns: i * 10_000_000,
            values: vec![
                Value::Time(plc_core::Time::from_millis(i as i64 * 10)),
                Value::Int(i as i64 / 50),
            ],
        })
        .collect();
    let texts = texts_of(&columns, &rows);
    assert!(texts.iter().any(|t| t == "timer.ET (s)"), "{texts:?}");
    assert!(
        texts.iter().any(|t| t == "s"),
        "the timer's axis: {texts:?}"
    );
    assert!(
        texts.iter().any(|t| t == "value"),
        "the counter's own axis: {texts:?}"
    );
}

#[test]
fn no_rows_one_row_constants_and_nans_still_draw() {
    let (columns, rows) = tensile(100, 2);
    let (texts, _) =
        parts(&svg("t", &columns, &Samples::from_rows(columns.len(), &[]), None).unwrap());
    assert!(texts.iter().any(|t| t == "no rows recorded"));
    let one = svg(
        "t",
        &columns,
        &Samples::from_rows(columns.len(), &rows[..1]),
        Some(rows[0].time_ns),
    )
    .unwrap();
    assert!(
        roxmltree::Document::parse(&one)
            .unwrap()
            .descendants()
            .any(|n| n.has_tag_name("circle"))
    );
    let mut odd = rows.clone();
    for (i, r) in odd.iter_mut().enumerate() {
        r.values[0] = Value::Real(7.5);
        r.values[1] = Value::Real(if i % 3 == 0 { f64::NAN } else { i as f64 });
    }
    let drawn = svg(
        "t",
        &columns,
        &Samples::from_rows(columns.len(), &odd),
        None,
    )
    .unwrap();
    assert!(!drawn.contains("NaN") && !drawn.contains("inf"));
    parts(&drawn);
    let texts = texts_of(&columns[2..], &rows);
    assert!(
        !texts.iter().any(|t| t == "value"),
        "no numeric panel for bools only"
    );
    let (texts, _) = parts(&svg("t", &[], &Samples::default(), None).unwrap());
    assert!(texts.iter().any(|t| t == "time from first row (s)"));
}

#[test]
fn sixty_four_variables_keep_a_legible_legend() {
    let columns: Vec<Column> = (0..64)
        .map(|i| match i % 4 {
            0 => column(&format!("bits[{i}]"), IecType::Bool, None),
            _ => column(&format!("axes[{i}].actual"), IecType::Real, Some("mm")),
        })
        .collect();
    let rows: Vec<Row> = (0..50u64)
        .map(|c| Row {
            cycle: c,
            time_ns: c * 1000,
            values: (0..64)
                .map(|i| {
                    if i % 4 == 0 {
                        Value::Bool(c % 2 == 0)
                    } else {
                        Value::Real((c + i) as f64)
                    }
                })
                .collect(),
        })
        .collect();
    let svg = svg(
        "t",
        &columns,
        &Samples::from_rows(columns.len(), &rows),
        None,
    )
    .unwrap();
    let (texts, _) = parts(&svg);
    for c in &columns {
        assert!(texts.iter().any(|t| t.starts_with(&c.path)), "{}", c.path);
    }
}

#[test]
fn a_minute_at_4_khz_is_decimated() {
    let (columns, rows) = tensile(4000, 60);
    let svg = svg(
        "t",
        &columns,
        &Samples::from_rows(columns.len(), &rows),
        Some(1_000_000_000),
    )
    .unwrap();
    let (_, lines) = parts(&svg);
    assert!(lines.iter().all(|(_, n)| *n <= 2 * 1200 + 2), "{lines:?}");
    assert!(svg.len() < 400_000, "{} bytes", svg.len());
    eprintln!("240,000 rows x 4 columns: {} bytes", svg.len());
}

/// Writes example pictures to look at: `cargo test -p plc-cli --bins -- --ignored`.
#[test]
#[ignore = "writes files to look at"]
fn writes_the_example_pictures() {
    let dir = std::env::temp_dir();
    let (columns, rows) = tensile(4000, 3);
    let one = svg(
        "tensile_tester — plc trace",
        &columns,
        &Samples::from_rows(columns.len(), &rows),
        Some(1_000_000_000),
    );
    std::fs::write(dir.join("trace-example.svg"), one.unwrap()).unwrap();
    let columns: Vec<Column> = (0..64)
        .map(|i| match i % 4 {
            0 => column(&format!("station[{i}].door_closed"), IecType::Bool, None),
            1 => column(&format!("station[{i}].force"), IecType::Real, Some("kN")),
            _ => column(&format!("station[{i}].strain"), IecType::Lreal, Some("%")),
        })
        .collect();
    let rows: Vec<Row> = (0..4000u64)
        .map(|c| Row {
            cycle: c,
            time_ns: c * 250_000,
            values: (0..64)
                .map(|i| {
                    let t = c as f64 / 4000.0 + i as f64 / 64.0;
                    match i % 4 {
                        0 => Value::Bool((t * 3.0).fract() < 0.5),
                        1 => Value::Real(40.0 * (t * 6.0).sin()),
                        _ => Value::Real(0.02 * (t * 4.0).cos()),
                    }
                })
                .collect(),
        })
        .collect();
    let many = svg(
        "64 values",
        &columns,
        &Samples::from_rows(columns.len(), &rows),
        Some(rows[1000].time_ns),
    );
    std::fs::write(dir.join("trace-example-64.svg"), many.unwrap()).unwrap();
}
