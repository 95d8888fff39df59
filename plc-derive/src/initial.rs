//! `initial = <literal>`: what was written and its JSON text for `VarInfo::initial`. Whether
//! it fits a type the tokens show is the declaration model's rule
//! (`plc_rules::decl::initial_misfit`); here are only the checks of a type only the compiler
//! knows (an alias).

use plc_rules::decl::{self, InitialValue};
use proc_macro2::{Span, TokenStream};
use quote::{quote, quote_spanned};
use syn::{Expr, Lit, UnOp};

#[derive(Clone, Debug)]
pub struct Initial {
    pub value: InitialValue,
    /// The JSON text: `12.5`, `-3`, `"TEST-001"`; for a bare integer beyond i128 the digits
    /// as written.
    pub text: String,
    /// The tokens written, so an error can cover all of `-1`, not just the `-`.
    pub tokens: TokenStream,
}

impl Initial {
    /// Reads a literal, optionally negated: `true`, `1500`, `-0.5`, `"TEST-001"`. `written` is
    /// the value's tokens as the user wrote them, which errors cover.
    pub fn parse(expr: &Expr, written: TokenStream) -> syn::Result<Initial> {
        let bad = || {
            syn::Error::new_spanned(
                &written,
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
            Expr::Group(g) => return Initial::parse(&g.expr, written),
            Expr::Paren(p) => return Initial::parse(&p.expr, written),
            _ => return Err(bad()),
        };
        let mut big_digits = None;
        let value = match lit {
            Lit::Bool(b) if !negative => InitialValue::Bool(b.value),
            Lit::Str(s) if !negative => InitialValue::Text(s.value()),
            Lit::Int(i) => match i.base10_parse::<i128>() {
                Ok(n) => InitialValue::Int(if negative { -n } else { n }),
                // Beyond every integer type, but a bare integer is fine for REAL/LREAL (IEC
                // 61131-3): keep the digits, judge the number against the field's type later.
                Err(_) => {
                    let digits = i.base10_digits();
                    let v: f64 = digits.parse().map_err(|_| bad())?;
                    finite(v, &written)?;
                    big_digits = Some(format!("{}{digits}", if negative { "-" } else { "" }));
                    InitialValue::BigInt(if negative { -v } else { v })
                }
            },
            Lit::Float(f) => {
                let v: f64 = f.base10_parse().map_err(|_| bad())?;
                finite(v, &written)?;
                InitialValue::Float(if negative { -v } else { v })
            }
            _ => return Err(bad()),
        };
        let text = match (&value, big_digits) {
            (_, Some(digits)) => digits,
            (InitialValue::Bool(b), _) => b.to_string(),
            (InitialValue::Int(i), _) => i.to_string(),
            (InitialValue::BigInt(f) | InitialValue::Float(f), _) => format!("{f:?}"),
            (InitialValue::Text(s), _) => json_string(s),
            (InitialValue::Other, _) => String::new(),
        };
        Ok(Initial {
            value,
            text,
            tokens: written,
        })
    }

    /// JSON text, as `VarInfo::initial` holds it.
    pub fn json(&self) -> String {
        self.text.clone()
    }

    /// The value as the declaration model holds it.
    pub fn to_decl(&self) -> decl::Initial {
        decl::Initial {
            value: self.value.clone(),
            text: self.text.clone(),
        }
    }

    /// An expression of type `Value` for the generated `Default`.
    pub fn value_tokens(&self, krate: &TokenStream) -> TokenStream {
        match &self.value {
            InitialValue::Bool(b) => quote!(#krate::Value::Bool(#b)),
            // Exact for every integer type; beyond i64/u64 only REAL/LREAL can hold the value
            // (the range checks reject it for integers), so it goes as the nearest f64.
            InitialValue::Int(n) => match (i64::try_from(*n), u64::try_from(*n)) {
                (_, Ok(u)) => quote!(#krate::Value::UInt(#u)),
                (Ok(i), _) => quote!(#krate::Value::Int(#i)),
                _ => {
                    let f = *n as f64;
                    quote!(#krate::Value::Real(#f))
                }
            },
            InitialValue::BigInt(f) | InitialValue::Float(f) => {
                quote!(#krate::Value::Real(#f))
            }
            InitialValue::Text(s) => {
                quote!(#krate::Value::Text(#krate::FixedString::<255>::from_str_truncate(#s)))
            }
            // The derive reads only literals; this is the JSON importer's "none of these".
            InitialValue::Other => quote!(#krate::Value::Bool(false)),
        }
    }

    /// The checks of the value against `ty`, a type only the compiler knows (an alias): pairs of
    /// a `const` condition and the message when it is false. First whether the value is of the
    /// type's kind, then (where that holds) whether it fits, so each mistake gets one message
    /// that says which it is. The type is named under its own span, so an unsupported type is
    /// reported there once.
    pub fn alias_checks(
        &self,
        krate: &TokenStream,
        ty: &syn::Type,
        ty_span: Span,
        field: &str,
    ) -> Vec<(TokenStream, String)> {
        let facts = quote_spanned!(ty_span=> #krate::__private::facts::<#ty>());
        let text = self.json();
        let out_of_range =
            format!("initial value {text} is out of range for the type of `{field}`");
        // A number literal: the type must be a number, and then `fits` must hold.
        let number = |fits: TokenStream| {
            vec![
                (
                    quote!(#facts.element_is_number()),
                    format!(
                        "initial value {text} is a number, but the type of `{field}` is not a \
                         number type"
                    ),
                ),
                (
                    quote!(!#facts.element_is_number() || #fits),
                    out_of_range.clone(),
                ),
            ]
        };
        match &self.value {
            InitialValue::Bool(_) => vec![(
                quote!(#facts.initial_bool_fits()),
                format!("initial value {text} is a bool, but the type of `{field}` is not bool"),
            )],
            InitialValue::Int(n) => number(quote!(#facts.initial_int_fits(#n))),
            // Beyond every integer type: a number, but only a real can hold it.
            InitialValue::BigInt(f) => number(quote!(#facts.initial_real_fits(#f))),
            InitialValue::Float(f) => vec![
                (
                    quote!(#facts.element_is_real()),
                    format!(
                        "initial value {text} is a real number, but the type of `{field}` is not \
                         f32 or f64 (real to integer is never implicit)"
                    ),
                ),
                (
                    quote!(!#facts.element_is_real() || #facts.initial_real_fits(#f)),
                    out_of_range,
                ),
            ],
            InitialValue::Text(s) => {
                let len = s.len();
                // A duration literal is text too; whether it is a valid one is known here.
                let time = plc_rules::Time::parse(s);
                let time_ok = time.is_ok();
                let time_problem = match time {
                    Ok(_) => String::new(),
                    Err(e) => e.to_string(),
                };
                vec![
                    (
                        quote!(#facts.element_is_string() || #facts.element_is_time()),
                        format!(
                            "initial value {text} is text, but the type of `{field}` is not a \
                             FixedString or a Time"
                        ),
                    ),
                    (
                        quote!(!#facts.element_is_string() || #facts.initial_str_fits(#len)),
                        format!(
                            "initial text {text} is {len} bytes, more than the type of `{field}` \
                             holds: shorten it or raise the capacity"
                        ),
                    ),
                    (
                        quote!(!#facts.element_is_time() || #time_ok),
                        format!(
                            "initial value {text} of `{field}`, a Time, is not a duration \
                             literal: {time_problem}"
                        ),
                    ),
                ]
            }
            InitialValue::Other => Vec::new(),
        }
    }
}

/// A number too large for f64 parses to infinity, which neither LREAL nor JSON can hold.
fn finite(v: f64, written: &TokenStream) -> syn::Result<()> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(syn::Error::new_spanned(
            written,
            format!(
                "this number is too large for any PLC type: LREAL (f64) holds up to {:e}",
                f64::MAX
            ),
        ))
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

    fn parse(src: &str) -> syn::Result<Initial> {
        let tokens: TokenStream = src.parse().unwrap();
        Initial::parse(&syn::parse2(tokens.clone()).unwrap(), tokens)
    }

    fn init(src: &str) -> Initial {
        parse(src).unwrap()
    }

    #[test]
    fn numbers_beyond_f64_are_errors_not_infinity() {
        for src in ["1e400", "-1e400", &"9".repeat(400)] {
            let e = parse(src).err().unwrap_or_else(|| panic!("{src} accepted"));
            assert!(e.to_string().contains("too large for any PLC type"), "{e}");
        }
    }

    #[test]
    fn integers_beyond_u64_go_to_reals_as_reals_not_wrapped() {
        let krate = quote!(::plc_core);
        let tokens = |src: &str| init(src).value_tokens(&krate).to_string();
        let expect = |value: TokenStream| quote!(::plc_core::Value::#value).to_string();
        let (pos, neg) = (1e20f64, -1e20f64);
        assert_eq!(tokens("100000000000000000000"), expect(quote!(Real(#pos))));
        assert_eq!(tokens("-100000000000000000000"), expect(quote!(Real(#neg))));
        assert_eq!(
            tokens("18446744073709551615"),
            expect(quote!(UInt(18446744073709551615u64)))
        );
        assert_eq!(
            tokens("-9223372036854775808"),
            expect(quote!(Int(-9223372036854775808i64)))
        );
        // Beyond i128: still a bare integer, its digits kept as written, and a real.
        let huge = init(&format!("1{}", "0".repeat(45)));
        assert_eq!(huge.json(), format!("1{}", "0".repeat(45)));
        assert!(
            huge.value_tokens(&krate)
                .to_string()
                .contains("Value :: Real")
        );
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
}
