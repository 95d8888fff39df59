//! The trace as CSV (RFC 4180): a header `cycle,time_s,<path>...`, then a line per row.
//!
//! - `time_s`: seconds from time zero, with nine decimals (the rows' nanoseconds, exactly):
//!   the trigger row when there is a trigger (rows before it are negative, `-0.000250000`),
//!   else the first row.
//! - Values at full precision: integers in decimal; a REAL as the shortest text that reads back
//!   as the same f32 (`0.1`, not the `0.10000000149011612` its f64 widening prints), an LREAL
//!   the shortest for its f64, both with an exponent outside 1e-5..1e16; BOOLs `1`/`0`;
//!   STRINGs as text, quoted when needed, and text a spreadsheet would run as a formula kept
//!   text: one quoting for every CSV the tool writes ([`csv_cell`]).
//! - LTIME in seconds with nine decimals, like `time_s`: a number a spreadsheet or a script
//!   plots and subtracts, where the IEC literal (`LTIME#1m30s`) would be text to parse.

use super::{Column, Row};
use crate::display::csv_cell;
use plc_core::{IecType, Value};
use std::fmt::{Display, LowerExp, Write as _};
use std::io::{self, Write};

/// Writes the header, then rows; see the [module documentation](self) for the format.
#[derive(Debug)]
pub struct CsvWriter<W: Write> {
    out: W,
    types: Vec<IecType>,
    origin_ns: Option<u64>,
    /// The line being built, kept to reuse its allocation.
    line: String,
}

impl<W: Write> CsvWriter<W> {
    /// Writes the header line for `columns` to `out`.
    pub fn new(mut out: W, columns: &[Column]) -> io::Result<CsvWriter<W>> {
        let mut line = String::from("cycle,time_s");
        for c in columns {
            line.push(',');
            line.push_str(&csv_cell(&c.path, false));
        }
        line.push('\n');
        out.write_all(line.as_bytes())?;
        Ok(CsvWriter {
            out,
            types: columns.iter().map(|c| c.iec_type).collect(),
            origin_ns: None,
            line,
        })
    }

    /// Sets time zero to the trigger row's time; call it before writing rows. Without a call,
    /// time zero is the first row's.
    pub fn set_origin(&mut self, time_ns: u64) {
        self.origin_ns = Some(time_ns);
    }

    /// Writes one row; a value the row lacks is an empty field.
    pub fn write_row(&mut self, row: &Row) -> io::Result<()> {
        let origin = *self.origin_ns.get_or_insert(row.time_ns);
        let line = &mut self.line;
        line.clear();
        // Writing to a String cannot fail.
        let _ = write!(line, "{},", row.cycle);
        seconds(line, row.time_ns as i128 - origin as i128);
        for (i, ty) in self.types.iter().enumerate() {
            line.push(',');
            if let Some(v) = row.values.get(i) {
                value(line, v, *ty);
            }
        }
        line.push('\n');
        self.out.write_all(line.as_bytes())
    }

    /// The writer, to flush or close.
    pub fn into_inner(self) -> W {
        self.out
    }
}

/// `ns` nanoseconds as seconds with nine decimals, from integers: no float rounding.
fn seconds(line: &mut String, ns: i128) {
    let sign = if ns < 0 { "-" } else { "" };
    let ns = ns.unsigned_abs();
    let _ = write!(
        line,
        "{sign}{}.{:09}",
        ns / 1_000_000_000,
        ns % 1_000_000_000
    );
}

/// One value; a REAL column's reals as f32.
fn value(line: &mut String, v: &Value, ty: IecType) {
    match v {
        Value::Bool(b) => line.push(if *b { '1' } else { '0' }),
        Value::Int(i) => {
            let _ = write!(line, "{i}");
        }
        Value::UInt(u) => {
            let _ = write!(line, "{u}");
        }
        Value::Real(r) if ty == IecType::Real => shortest(line, *r as f32),
        Value::Real(r) => shortest(line, *r),
        Value::Text(t) => line.push_str(&csv_cell(t.as_str(), true)),
        Value::Time(t) => seconds(line, t.as_nanos() as i128),
    }
}

/// The shortest text that reads back as `v` (Rust's float formatting guarantees it), with an
/// exponent where plain digits would run long (`1e-7`, `3.4028235e38`).
fn shortest<F: Display + LowerExp + Into<f64> + Copy>(line: &mut String, v: F) {
    let abs = v.into().abs();
    let _ = if abs == 0.0 || !abs.is_finite() || (1e-5..1e16).contains(&abs) {
        write!(line, "{v}")
    } else {
        write!(line, "{v:e}")
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::{FixedString, Time};

    fn column(path: &str, iec_type: IecType) -> Column {
        Column {
            path: path.into(),
            iec_type,
            unit: None,
        }
    }

    fn row(cycle: u64, time_ns: u64, values: Vec<Value>) -> Row {
        Row {
            cycle,
            time_ns,
            values,
        }
    }

    /// The CSV text of `rows`, time zero at `origin` if given.
    fn csv(columns: &[Column], rows: &[Row], origin: Option<u64>) -> String {
        let mut w = CsvWriter::new(Vec::new(), columns).unwrap();
        if let Some(o) = origin {
            w.set_origin(o);
        }
        for r in rows {
            w.write_row(r).unwrap();
        }
        String::from_utf8(w.into_inner()).unwrap()
    }

    #[test]
    fn header_quotes_paths_that_need_it() {
        let cols = [
            column("force_kn", IecType::Real),
            column("grid[2,1].ok", IecType::Bool),
            column("say\"hi\"", IecType::Bool),
        ];
        assert_eq!(
            csv(&cols, &[], None),
            "cycle,time_s,force_kn,\"grid[2,1].ok\",\"say\"\"hi\"\"\"\n"
        );
    }

    #[test]
    fn time_is_relative_to_the_trigger_with_nanosecond_precision() {
        let cols = [column("n", IecType::Dint)];
        let rows = [
            row(7, 1_000_000_000, vec![Value::Int(-1)]),
            row(8, 1_000_250_000, vec![Value::UInt(2)]),
            row(9, 3_500_000_001, vec![Value::UInt(3)]),
        ];
        assert_eq!(
            csv(&cols, &rows, Some(1_000_250_000)),
            "cycle,time_s,n\n7,-0.000250000,-1\n8,0.000000000,2\n9,2.499750001,3\n"
        );
    }

    #[test]
    fn without_a_trigger_time_zero_is_the_first_row() {
        let cols = [column("b", IecType::Bool)];
        let rows = [
            row(1, 5_000, vec![Value::Bool(true)]),
            row(2, 6_000, vec![Value::Bool(false)]),
        ];
        assert_eq!(
            csv(&cols, &rows, None),
            "cycle,time_s,b\n1,0.000000000,1\n2,0.000001000,0\n"
        );
    }

    #[test]
    fn reals_are_the_shortest_text_that_reads_back() {
        let cols = [column("r", IecType::Real), column("l", IecType::Lreal)];
        let line = |r: f32, l: f64| {
            let text = csv(
                &cols,
                &[row(0, 0, vec![Value::Real(r as f64), Value::Real(l)])],
                None,
            );
            text.lines().nth(1).unwrap().to_string()
        };
        assert_eq!(line(0.1, 0.1), "0,0.000000000,0.1,0.1");
        assert_eq!(
            line(1.0 / 3.0, 1.0 / 3.0),
            "0,0.000000000,0.33333334,0.3333333333333333"
        );
        assert_eq!(line(f32::MAX, 1e-7), "0,0.000000000,3.4028235e38,1e-7");
        assert_eq!(line(-2.5, f64::NAN), "0,0.000000000,-2.5,NaN");
        for r in [0.1f32, 1.0 / 3.0, f32::MAX, f32::MIN_POSITIVE, 123456.79] {
            let text = line(r, 0.0);
            assert_eq!(text.split(',').nth(2).unwrap().parse::<f32>(), Ok(r));
        }
    }

    #[test]
    fn durations_are_seconds_and_text_is_quoted() {
        let cols = [column("t", IecType::Ltime), column("s", IecType::String)];
        let text = FixedString::from_str_truncate("a,b");
        let rows = [row(
            0,
            0,
            vec![Value::Time(Time::from_micros(-1500)), Value::Text(text)],
        )];
        assert_eq!(
            csv(&cols, &rows, None).lines().nth(1),
            Some("0,0.000000000,-0.001500000,\"a,b\"")
        );
    }

    #[test]
    fn text_a_spreadsheet_would_run_stays_text_and_numbers_stay_numbers() {
        let cols = [column("s", IecType::String), column("x", IecType::Lreal)];
        let formula = FixedString::from_str_truncate("=HYPERLINK(\"x\")");
        let rows = [row(0, 0, vec![Value::Text(formula), Value::Real(-1.5)])];
        assert_eq!(
            csv(&cols, &rows, None).lines().nth(1),
            Some("0,0.000000000,\"'=HYPERLINK(\"\"x\"\")\",-1.5")
        );
    }

    #[test]
    fn a_missing_value_is_an_empty_field() {
        let cols = [column("a", IecType::Dint), column("b", IecType::Dint)];
        let rows = [row(0, 0, vec![Value::Int(1)])];
        assert_eq!(
            csv(&cols, &rows, None).lines().nth(1),
            Some("0,0.000000000,1,")
        );
    }
}
