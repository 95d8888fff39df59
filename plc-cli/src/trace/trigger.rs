//! `--trigger EXPR`: `PATH > VALUE`, `PATH < VALUE`, `PATH == VALUE`, `PATH rising`,
//! `PATH falling`.
//!
//! Parsed in two steps because the value's syntax depends on the variable's type, which only
//! the segment knows: [`Trigger::parse`] splits the text into a path and a condition before
//! the segment is attached (so a typo fails at once), [`TriggerSpec::bind`] reads the value
//! once the path is resolved to a column.
//!
//! A trigger fires on the edge of its condition, as TwinCAT Scope's does: on the first row
//! where it holds after a row where it did not. A condition already true when the trace starts
//! waits until it has been false once; `rising` is the edge of `== TRUE`, `falling` of
//! `== FALSE`.

use super::Row;
use plc_core::{IecType, TypeFamily, Value};
use std::cmp::Ordering;

/// What the error messages offer when an expression has none of the forms.
const FORMS: &str =
    "write `PATH > VALUE`, `PATH < VALUE`, `PATH == VALUE`, `PATH rising` or `PATH falling`";

/// The operator of an expression.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Op {
    Above,
    Below,
    Equal,
    Rising,
    Falling,
}

impl Op {
    /// As the user writes it.
    fn text(self) -> &'static str {
        match self {
            Op::Above => ">",
            Op::Below => "<",
            Op::Equal => "==",
            Op::Rising => "rising",
            Op::Falling => "falling",
        }
    }
}

/// A trigger expression split into its path and condition; the value is still text.
#[derive(Clone, Debug, PartialEq)]
pub struct TriggerSpec {
    /// The expression as given, trimmed, for error messages.
    expr: String,
    path: String,
    op: Op,
    /// The value's text; empty for `rising` and `falling`.
    operand: String,
}

/// A trigger bound to its column: it watches the rows and says when its condition becomes
/// true.
#[derive(Clone, Debug, PartialEq)]
pub struct Trigger {
    column: usize,
    op: Op,
    value: Value,
    /// Whether the condition held on the previous row; `None` before the first row and after
    /// a gap, when there is no previous row to make an edge with.
    held: Option<bool>,
}

impl Trigger {
    /// Splits `expr` into a path and a condition. Whitespace around the operator and inside
    /// brackets is ignored (`axes[1, 2].pos>3`); a path has none elsewhere.
    pub fn parse(expr: &str) -> Result<TriggerSpec, String> {
        let text = expr.trim();
        let fail = |why: String| format!("`{text}`: {why}");
        let (path, op, operand) = if let Some(at) = text.find(['<', '>', '=', '!']) {
            let (path, rest) = text.split_at(at);
            let (op, operand) = if let Some(v) = rest.strip_prefix("==") {
                (Op::Equal, v)
            } else if [">=", "<=", "!="].iter().any(|o| rest.starts_with(o)) {
                return Err(fail(format!(
                    "`{}` is not offered: the trace starts on the cycle the condition becomes \
                     true, so {FORMS}",
                    &rest[..2]
                )));
            } else if let Some(v) = rest.strip_prefix('>') {
                (Op::Above, v)
            } else if let Some(v) = rest.strip_prefix('<') {
                (Op::Below, v)
            } else {
                return Err(fail("compare with `==`, not `=` or `!`".into()));
            };
            let operand = operand.trim();
            if operand.is_empty() {
                return Err(fail(format!(
                    "no value after `{}`: write e.g. `{} {} 10`",
                    op.text(),
                    path.trim(),
                    op.text()
                )));
            }
            (path, op, operand)
        } else {
            let (path, word) = text.rsplit_once(char::is_whitespace).unwrap_or(("", text));
            let op = match word.to_ascii_lowercase().as_str() {
                "rising" => Op::Rising,
                "falling" => Op::Falling,
                _ => return Err(fail(format!("no condition: {FORMS}"))),
            };
            (path, op, "")
        };
        Ok(TriggerSpec {
            expr: text.to_string(),
            path: clean_path(path).map_err(fail)?,
            op,
            operand: operand.to_string(),
        })
    }

    /// Takes the next row; true if the condition holds on it and did not on the row before.
    pub fn fires(&mut self, row: &Row) -> bool {
        let holds = self.holds(row);
        let edge = holds && self.held == Some(false);
        self.held = Some(holds);
        edge
    }

    /// Forgets the previous row: rows were lost, and an edge across the loss is not one the
    /// trace saw.
    pub fn reset(&mut self) {
        self.held = None;
    }

    /// Whether the condition holds on `row` (a value missing or of another kind: no).
    fn holds(&self, row: &Row) -> bool {
        let Some(ord) = row
            .values
            .get(self.column)
            .and_then(|v| compare(v, &self.value))
        else {
            return false;
        };
        match self.op {
            Op::Above => ord == Ordering::Greater,
            Op::Below => ord == Ordering::Less,
            Op::Equal | Op::Rising | Op::Falling => ord == Ordering::Equal,
        }
    }
}

impl TriggerSpec {
    /// The variable's path, to resolve to a column.
    pub fn path(&self) -> &str {
        &self.path
    }

    /// The trigger on column `column` of type `iec_type`, with the value read for that type.
    pub fn bind(&self, column: usize, iec_type: IecType) -> Result<Trigger, String> {
        let fail = |why: String| format!("`{}`: {why}", self.expr);
        let path = &self.path;
        let value = match (iec_type.family(), self.op) {
            (TypeFamily::String, _) => {
                return Err(fail(format!(
                    "`{path}` is a STRING, which cannot trigger a trace: trigger on a BOOL, a \
                     number or an LTIME"
                )));
            }
            (TypeFamily::Bool, Op::Rising) => Value::Bool(true),
            (TypeFamily::Bool, Op::Falling) => Value::Bool(false),
            (_, Op::Rising | Op::Falling) => {
                return Err(fail(format!(
                    "`{}` is for BOOL variables and `{path}` is {iec_type}: write `{path} > \
                     VALUE` or `{path} < VALUE`",
                    self.op.text()
                )));
            }
            (TypeFamily::Bool, Op::Above | Op::Below) => {
                return Err(fail(format!(
                    "`{path}` is a BOOL: write `{path} rising`, `{path} falling` or `{path} == \
                     TRUE`"
                )));
            }
            _ => self.value(iec_type).map_err(fail)?,
        };
        Ok(Trigger {
            column,
            op: self.op,
            value,
            held: None,
        })
    }

    /// The operand read as a value of `iec_type`.
    fn value(&self, iec_type: IecType) -> Result<Value, String> {
        let (text, path) = (&self.operand, &self.path);
        match Value::parse(text, iec_type) {
            // A REAL row holds an f32 widened to f64: compare with the f32 nearest the text,
            // or `x > 0.1` would fire on x = 0.1, which as f32 is 0.100000001.
            Ok(Value::Real(v)) if v.is_finite() && iec_type == IecType::Real => {
                Ok(Value::Real(v as f32 as f64))
            }
            Ok(Value::Real(v)) if !v.is_finite() => Err(format!(
                "`{text}` is not a finite number: compare `{path}` with a number"
            )),
            Ok(v) => Ok(v),
            Err(e) => Err(format!(
                "`{text}` is not a {iec_type} value for `{path}`: {e}"
            )),
        }
    }
}

/// The path with the spaces inside brackets removed; an error for spaces elsewhere or no path.
fn clean_path(raw: &str) -> Result<String, String> {
    let raw = raw.trim();
    if raw.is_empty() {
        return Err(format!("no variable before the condition: {FORMS}"));
    }
    let mut path = String::with_capacity(raw.len());
    let mut depth = 0usize;
    for c in raw.chars() {
        match c {
            '[' => depth += 1,
            ']' => depth = depth.saturating_sub(1),
            c if c.is_whitespace() && depth > 0 => continue,
            c if c.is_whitespace() => {
                return Err(format!(
                    "`{raw}` is not a variable path: a path has no spaces (e.g. \
                     `axes[1].actual`); {FORMS}"
                ));
            }
            _ => {}
        }
        path.push(c);
    }
    Ok(path)
}

/// How `a` compares with `b`: integers exactly, reals and mixed numbers as f64, durations and
/// bools as themselves; `None` for NaN or values of different kinds.
fn compare(a: &Value, b: &Value) -> Option<Ordering> {
    let real = |v: &Value| match *v {
        Value::Real(r) => Some(r),
        Value::Int(i) => Some(i as f64),
        Value::UInt(u) => Some(u as f64),
        _ => None,
    };
    match (a, b) {
        (Value::Bool(x), Value::Bool(y)) => Some(x.cmp(y)),
        (Value::Time(x), Value::Time(y)) => Some(x.cmp(y)),
        (Value::Real(_), _) | (_, Value::Real(_)) => real(a)?.partial_cmp(&real(b)?),
        _ => Some(a.as_i128()?.cmp(&b.as_i128()?)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use plc_core::Time;

    fn row(v: Value) -> Row {
        Row {
            cycle: 0,
            time_ns: 0,
            values: vec![v],
        }
    }

    fn bound(expr: &str, ty: IecType) -> Trigger {
        Trigger::parse(expr).unwrap().bind(0, ty).unwrap()
    }

    /// Which of `values` the trigger fires on.
    fn fired(mut t: Trigger, values: &[Value]) -> Vec<usize> {
        (0..values.len())
            .filter(|&i| t.fires(&row(values[i])))
            .collect()
    }

    #[test]
    fn parse_splits_path_and_condition_ignoring_whitespace() {
        for (expr, path, op, operand) in [
            ("force_kn > 2.5", "force_kn", Op::Above, "2.5"),
            ("  force_kn>2.5 ", "force_kn", Op::Above, "2.5"),
            ("axes[1, 2].pos < -3", "axes[1,2].pos", Op::Below, "-3"),
            ("state == 4", "state", Op::Equal, "4"),
            ("door.closed rising", "door.closed", Op::Rising, ""),
            ("grid[ 2 ,1 ].ok  FALLING", "grid[2,1].ok", Op::Falling, ""),
        ] {
            let spec = Trigger::parse(expr).unwrap();
            assert_eq!(
                (spec.path(), spec.op, spec.operand.as_str()),
                (path, op, operand),
                "{expr}"
            );
        }
    }

    #[test]
    fn parse_errors_name_the_expression_and_what_to_write() {
        for (expr, says) in [
            ("force_kn", "no condition: write `PATH > VALUE`"),
            ("force_kn >= 3", "`>=` is not offered"),
            ("force_kn != 3", "`!=` is not offered"),
            ("force_kn = 3", "compare with `==`"),
            (
                "force_kn >",
                "no value after `>`: write e.g. `force_kn > 10`",
            ),
            ("> 3", "no variable before the condition"),
            ("rising", "no variable before the condition"),
            (
                "force kn > 3",
                "`force kn` is not a variable path: a path has no spaces",
            ),
        ] {
            let e = Trigger::parse(expr).unwrap_err();
            assert!(e.starts_with(&format!("`{expr}`: ")), "{e}");
            assert!(e.contains(says), "{expr}: {e}");
        }
    }

    #[test]
    fn bind_refuses_conditions_the_type_does_not_have() {
        for (expr, ty, says) in [
            (
                "name == x",
                IecType::String,
                "`name` is a STRING, which cannot trigger",
            ),
            (
                "f rising",
                IecType::Real,
                "`rising` is for BOOL variables and `f` is REAL: write `f > VALUE`",
            ),
            (
                "b > 0",
                IecType::Bool,
                "`b` is a BOOL: write `b rising`, `b falling` or `b == TRUE`",
            ),
            (
                "n > abc",
                IecType::Dint,
                "`abc` is not a DINT value for `n`: expected a whole number",
            ),
            (
                "n > 300",
                IecType::Usint,
                "`300` is not a USINT value for `n`: out of range",
            ),
            ("t > 5", IecType::Ltime, "`5` is not a LTIME value for `t`"),
            ("f > NaN", IecType::Lreal, "`NaN` is not a finite number"),
        ] {
            let e = Trigger::parse(expr).unwrap().bind(0, ty).unwrap_err();
            assert!(e.contains(says), "{expr}: {e}");
        }
    }

    #[test]
    fn fires_on_the_first_row_where_the_condition_becomes_true() {
        let v = |x: f64| Value::Real(x);
        let t = bound("f > 1.5", IecType::Lreal);
        assert_eq!(
            fired(t, &[v(0.0), v(1.0), v(2.0), v(3.0), v(1.0), v(2.0)]),
            [2, 5]
        );
    }

    #[test]
    fn a_condition_true_from_the_start_waits_until_it_was_false() {
        let b = Value::Bool;
        let t = bound("b rising", IecType::Bool);
        assert_eq!(fired(t, &[b(true), b(true), b(false), b(true)]), [3]);
        let t = bound("b falling", IecType::Bool);
        assert_eq!(fired(t, &[b(false), b(true), b(false)]), [2]);
    }

    #[test]
    fn reset_forgets_the_row_before_a_gap() {
        let mut t = bound("n > 0", IecType::Dint);
        assert!(!t.fires(&row(Value::Int(-1))));
        t.reset();
        assert!(!t.fires(&row(Value::UInt(5))), "no edge across the gap");
    }

    #[test]
    fn real_thresholds_compare_as_the_f32_the_row_holds() {
        let tenth = Value::Real(0.1f32 as f64);
        let t = bound("x > 0.1", IecType::Real);
        assert_eq!(fired(t, &[Value::Real(0.0), tenth]), [] as [usize; 0]);
        let t = bound("x == 0.1", IecType::Real);
        assert_eq!(fired(t, &[Value::Real(0.0), tenth]), [1]);
    }

    #[test]
    fn integers_durations_and_bool_equality_compare_as_their_kind() {
        let t = bound("n < -2", IecType::Lint);
        assert_eq!(fired(t, &[Value::UInt(3), Value::Int(-3)]), [1]);
        let t = bound("t > T#1s", IecType::Ltime);
        let ms = |m| Value::Time(Time::from_millis(m));
        assert_eq!(fired(t, &[ms(1000), ms(1001)]), [1]);
        let t = bound("b == TRUE", IecType::Bool);
        assert_eq!(fired(t, &[Value::Bool(false), Value::Bool(true)]), [1]);
    }

    #[test]
    fn a_nan_does_not_hold_so_the_row_after_it_can_fire() {
        let t = bound("f < 1", IecType::Lreal);
        let (zero, nan) = (Value::Real(0.0), Value::Real(f64::NAN));
        assert_eq!(fired(t, &[zero, nan, zero]), [2]);
    }
}
