//! `alarm = "text"` and `alarm(text = "...", ...)` in a field's `#[plc(...)]`: read into the
//! declaration model's [`Alarm`], every value keeping its tokens so the checker's issues point
//! at them. Whether the alarm makes sense on its field is the model's rule
//! (`plc_rules::decl`); here is only the syntax.

use crate::loc::{At, Loc};
use darling::FromMeta;
use plc_rules::decl::{Alarm, LIMIT_KEYS};
use quote::ToTokens;
use syn::spanned::Spanned;
use syn::{Expr, Lit, Meta, UnOp};

/// The keys of `alarm(...)`.
pub const ALARM_KEYS: &[&str] = &[
    "text",
    "severity",
    "delay",
    "latched",
    "suppress_when",
    "alarm_when",
    "low_low",
    "low",
    "high",
    "high_high",
    "deadband",
];

/// The alarm of a field, as the model holds it.
pub struct AlarmAttr(pub Alarm<Loc>);

impl FromMeta for AlarmAttr {
    fn from_meta(item: &Meta) -> darling::Result<Self> {
        let at = Loc::Span(item.path().span());
        match item {
            Meta::NameValue(nv) => {
                let text = string(&nv.value, "alarm")?;
                Ok(AlarmAttr(Alarm::new(at, text)))
            }
            Meta::List(list) => {
                let nested = list
                    .parse_args_with(
                        syn::punctuated::Punctuated::<Meta, syn::Token![,]>::parse_terminated,
                    )
                    .map_err(darling::Error::from)?;
                from_list(at, list, nested.iter())
            }
            Meta::Path(p) => Err(darling::Error::custom(
                "`alarm` needs its text: write `alarm = \"Guard door open\"` or \
                 `alarm(text = \"...\", ...)`",
            )
            .with_span(p)),
        }
    }
}

fn from_list<'a>(
    at: Loc,
    list: &syn::MetaList,
    items: impl Iterator<Item = &'a Meta>,
) -> darling::Result<AlarmAttr> {
    let mut errors = darling::Error::accumulator();
    let mut text = None;
    let mut alarm = Alarm::new(at.clone(), At::new(String::new(), at));
    let mut seen: Vec<String> = Vec::new();
    for item in items {
        let key = item
            .path()
            .get_ident()
            .map_or_else(String::new, ToString::to_string);
        if seen.contains(&key) {
            errors.push(
                darling::Error::custom(format!("`{key}` is given twice in `alarm(...)`: keep one"))
                    .with_span(item.path()),
            );
            continue;
        }
        seen.push(key.clone());
        if key == "latched" {
            match item {
                Meta::Path(p) => alarm.latched = Some(Loc::Span(p.span())),
                _ => errors.push(
                    darling::Error::custom(
                        "`latched` is a flag and takes no value: write `latched` alone (leave \
                         it out for an alarm that clears by itself)",
                    )
                    .with_span(item),
                ),
            }
            continue;
        }
        if !ALARM_KEYS.contains(&key.as_str()) {
            errors.push(
                darling::Error::custom(format!(
                    "unknown key `{key}` in `alarm(...)`: the keys are {}",
                    crate::symbol::list(ALARM_KEYS.iter().copied())
                ))
                .with_span(item.path()),
            );
            continue;
        }
        let Meta::NameValue(nv) = item else {
            errors.push(
                darling::Error::custom(format!("`{key}` needs a value: write `{key} = ...`"))
                    .with_span(item),
            );
            continue;
        };
        let value = &nv.value;
        // The whole of `-0.5` as written, not syn's literal spanned by the `-` alone.
        let written = crate::raw_value::value_in(list.tokens.clone(), &key)
            .map_or_else(|| loc(value), Loc::Tokens);
        let read = match key.as_str() {
            "text" => string(value, "text").map(|t| text = Some(t)),
            "delay" => string(value, "delay").map(|d| alarm.delay = Some(d)),
            "suppress_when" => {
                string(value, "suppress_when").map(|s| alarm.suppress_when = Some(s))
            }
            "alarm_when" => boolean(value).map(|w| alarm.when = Some(w)),
            "severity" => integer(value, written).map(|s| alarm.severity = Some(s)),
            "deadband" => number(value, written, "deadband").map(|d| alarm.deadband = Some(d)),
            limit => {
                let i = LIMIT_KEYS.iter().position(|k| *k == limit).unwrap_or(0);
                number(value, written, limit).map(|n| alarm.limits[i] = Some(n))
            }
        };
        errors.handle(read);
    }
    match text {
        Some(t) => alarm.text = t,
        None => errors.push(
            darling::Error::custom(
                "`alarm(...)` needs `text = \"...\"`: the message operators see when it is raised",
            )
            .with_span(&list.path),
        ),
    }
    errors.finish_with(AlarmAttr(alarm))
}

/// A literal without the groups a macro may wrap it in, and whether a `-` precedes it.
pub fn literal(expr: &Expr) -> Option<(bool, &Lit)> {
    match expr {
        Expr::Lit(l) => Some((false, &l.lit)),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => match &*u.expr {
            Expr::Lit(l) => Some((true, &l.lit)),
            _ => None,
        },
        Expr::Group(g) => literal(&g.expr),
        Expr::Paren(p) => literal(&p.expr),
        _ => None,
    }
}

/// Where an error about a value goes: all of its tokens (`-0.5`, not only the `-`).
fn loc(expr: &Expr) -> Loc {
    Loc::Tokens(expr.to_token_stream())
}

fn wrong(expr: &Expr, message: String) -> darling::Error {
    darling::Error::custom(message).with_span(expr)
}

fn string(expr: &Expr, key: &str) -> darling::Result<At<String>> {
    match literal(expr) {
        Some((false, Lit::Str(s))) => Ok(At::new(s.value(), Loc::Span(s.span()))),
        _ => Err(wrong(
            expr,
            format!(
                "`{key}` takes a string, such as {}",
                match key {
                    "delay" => "\"2s\"",
                    "suppress_when" => "\"out_of_service\"",
                    _ => "\"Guard door open\"",
                }
            ),
        )),
    }
}

fn boolean(expr: &Expr) -> darling::Result<At<bool>> {
    match literal(expr) {
        Some((false, Lit::Bool(b))) => Ok(At::new(b.value, Loc::Span(b.span()))),
        _ => Err(wrong(expr, "`alarm_when` takes `true` or `false`".into())),
    }
}

fn integer(expr: &Expr, written: Loc) -> darling::Result<At<i64>> {
    let bad = || {
        wrong(
            expr,
            "`severity` takes a whole number 1..=1000, such as `700`".into(),
        )
    };
    match literal(expr) {
        Some((negative, Lit::Int(i))) => {
            // Beyond i64 is out of range all the same: the checker says which range.
            let n = i.base10_parse::<i64>().unwrap_or(i64::MAX);
            Ok(At::new(if negative { -n } else { n }, written))
        }
        _ => Err(bad()),
    }
}

fn number(expr: &Expr, written: Loc, key: &str) -> darling::Result<At<f64>> {
    let bad = || {
        wrong(
            expr,
            format!("`{key}` takes a number, such as `80.0` or `-5`"),
        )
    };
    let (negative, v) = match literal(expr) {
        Some((negative, Lit::Int(i))) => (negative, i.base10_parse::<f64>().map_err(|_| bad())?),
        Some((negative, Lit::Float(f))) => (negative, f.base10_parse::<f64>().map_err(|_| bad())?),
        _ => return Err(bad()),
    };
    if !v.is_finite() {
        return Err(bad());
    }
    Ok(At::new(if negative { -v } else { v }, written))
}
