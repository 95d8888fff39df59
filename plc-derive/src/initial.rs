//! `initial = <literal>`: what was written, its JSON text for `VarInfo::initial`, and whether
//! it fits the field's type.

use crate::types::KnownType;
use plc_rules::{IecType, TypeFamily};
use proc_macro2::{Span, TokenStream};
use quote::{quote, quote_spanned};
use syn::spanned::Spanned;
use syn::{Expr, Lit, UnOp};

#[derive(Clone, Debug, PartialEq)]
pub enum InitialValue {
    Bool(bool),
    Int(i128),
    Float(f64),
    Str(String),
}

#[derive(Clone, Debug)]
pub struct Initial {
    pub value: InitialValue,
    pub span: Span,
    /// The tokens written, so an error can cover all of `-1`, not just the `-`.
    pub tokens: TokenStream,
}

impl Initial {
    /// Reads a literal, optionally negated: `true`, `1500`, `-0.5`, `"TEST-001"`.
    pub fn parse(expr: &Expr) -> syn::Result<Initial> {
        let span = expr.span();
        let bad = || {
            syn::Error::new_spanned(
                expr,
                "`initial` takes a literal: a number (`12.5`, `-3`), `true`/`false`, or a string \
                 (`\"TEST-001\"`)",
            )
        };
        let (negative, lit) = match expr {
            Expr::Lit(l) => (false, &l.lit),
            Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => match &*u.expr {
                Expr::Lit(l) => (true, &l.lit),
                _ => return Err(bad()),
            },
            Expr::Group(g) => return Initial::parse(&g.expr),
            Expr::Paren(p) => return Initial::parse(&p.expr),
            _ => return Err(bad()),
        };
        let value = match lit {
            Lit::Bool(b) if !negative => InitialValue::Bool(b.value),
            Lit::Str(s) if !negative => InitialValue::Str(s.value()),
            Lit::Int(i) => {
                let n: i128 = i.base10_parse().map_err(|_| {
                    syn::Error::new_spanned(
                        expr,
                        "this number is too large for any PLC integer type",
                    )
                })?;
                InitialValue::Int(if negative { -n } else { n })
            }
            Lit::Float(f) => {
                let v: f64 = f.base10_parse().map_err(|_| bad())?;
                InitialValue::Float(if negative { -v } else { v })
            }
            _ => return Err(bad()),
        };
        Ok(Initial {
            value,
            span,
            tokens: quote!(#expr),
        })
    }

    /// JSON text, as `VarInfo::initial` holds it.
    pub fn json(&self) -> String {
        match &self.value {
            InitialValue::Bool(b) => b.to_string(),
            InitialValue::Int(i) => i.to_string(),
            InitialValue::Float(f) => format!("{f:?}"),
            InitialValue::Str(s) => json_string(s),
        }
    }

    /// What to say when the value does not fit a field of `known` type named `field`.
    pub fn misfit(&self, known: &KnownType, field: &str) -> Option<String> {
        let ty = known.element_name();
        let iec = known.iec;
        let kind = |what: &str| format!("`{field}` is {ty} ({iec}): `initial` must be {what}");
        match (&self.value, iec.family()) {
            (InitialValue::Bool(_), TypeFamily::Bool) => None,
            (_, TypeFamily::Bool) => Some(kind("`true` or `false`")),
            (InitialValue::Int(n), f) if iec.is_integer() || f == TypeFamily::Real => {
                let (lo, hi) = iec.int_range().unwrap_or((i128::MIN, i128::MAX));
                (*n < lo || *n > hi).then(|| {
                    format!(
                        "initial value {n} is out of range for `{field}` ({ty} holds {lo}..={hi})"
                    )
                })
            }
            (InitialValue::Float(v), TypeFamily::Real) => {
                (iec == IecType::Real && v.is_finite() && v.abs() > f32::MAX as f64)
                    .then(|| format!("initial value {v:e} is out of range for `{field}` (f32)"))
            }
            (InitialValue::Float(_), _) if iec.is_integer() => {
                Some(kind("a whole number (real to integer is never implicit)"))
            }
            (InitialValue::Str(s), TypeFamily::String) => {
                let cap = known.capacity.unwrap_or(u64::MAX);
                (s.len() as u64 > cap).then(|| {
                    format!(
                        "initial text of {} bytes does not fit `{field}` ({ty} holds {cap} bytes): \
                         shorten it or raise the capacity",
                        s.len()
                    )
                })
            }
            (_, TypeFamily::String) => Some(kind("a string literal such as \"TEST-001\"")),
            (_, _) if iec.is_integer() => Some(kind("a whole number")),
            _ => Some(kind("a number")),
        }
    }

    /// An expression of type `Value` for the generated `Default`.
    pub fn value_tokens(&self, krate: &TokenStream) -> TokenStream {
        match &self.value {
            InitialValue::Bool(b) => quote!(#krate::Value::Bool(#b)),
            InitialValue::Int(n) if *n < 0 => {
                let n = *n as i64;
                quote!(#krate::Value::Int(#n))
            }
            InitialValue::Int(n) => {
                let n = *n as u64;
                quote!(#krate::Value::UInt(#n))
            }
            InitialValue::Float(f) => quote!(#krate::Value::Real(#f)),
            InitialValue::Str(s) => {
                quote!(#krate::Value::Text(#krate::FixedString::<255>::from_str_truncate(#s)))
            }
        }
    }

    /// A `const` expression true when the value fits `ty` (for types only the compiler knows).
    /// The type is named under its own span, so an unsupported type is reported there once.
    pub fn fits_tokens(&self, krate: &TokenStream, ty: &syn::Type, ty_span: Span) -> TokenStream {
        let facts = quote_spanned!(ty_span=> #krate::__private::facts::<#ty>());
        match &self.value {
            InitialValue::Bool(_) => quote!(#facts.initial_bool_fits()),
            InitialValue::Int(n) => quote!(#facts.initial_int_fits(#n)),
            InitialValue::Float(f) => quote!(#facts.initial_real_fits(#f)),
            InitialValue::Str(s) => {
                let len = s.len();
                quote!(#facts.initial_str_fits(#len))
            }
        }
    }
}

/// A JSON string literal.
pub fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn init(src: &str) -> Initial {
        Initial::parse(&syn::parse_str(src).unwrap()).unwrap()
    }

    #[test]
    fn json_text_of_each_kind() {
        assert_eq!(init("12.5").json(), "12.5");
        assert_eq!(init("-0.5").json(), "-0.5");
        assert_eq!(init("1500").json(), "1500");
        assert_eq!(init("-3").json(), "-3");
        assert_eq!(init("true").json(), "true");
        assert_eq!(init("\"a \\\"b\\\"\"").json(), "\"a \\\"b\\\"\"");
    }

    #[test]
    fn misfits_are_explained() {
        let u8t = KnownType {
            iec: IecType::Usint,
            capacity: None,
            dims: vec![],
        };
        assert!(init("255").misfit(&u8t, "x").is_none());
        assert_eq!(
            init("256").misfit(&u8t, "x").unwrap(),
            "initial value 256 is out of range for `x` (u8 holds 0..=255)"
        );
        assert!(init("1.5").misfit(&u8t, "x").is_some());
        let f = KnownType {
            iec: IecType::Real,
            capacity: None,
            dims: vec![],
        };
        assert!(
            init("3").misfit(&f, "x").is_none(),
            "bare integers are fine for REAL (seed 001)"
        );
        let s = KnownType {
            iec: IecType::String,
            capacity: Some(3),
            dims: vec![],
        };
        assert!(init("\"abcd\"").misfit(&s, "x").is_some());
        assert!(init("\"abc\"").misfit(&s, "x").is_none());
    }
}
