//! What the tokens of a field's type tell without the compiler: enough to give precise errors
//! for the common case (`u16`, `FixedString<64>`, `[[f32; 4]; 3]`). A type the tokens do not
//! reveal (an alias) is `Unknown`, and its checks become `const` assertions on `PlcType`.

use plc_rules::IecType;
pub use plc_rules::decl::KnownType;
use syn::{Expr, GenericArgument, Lit, PathArguments, Type};

/// A field type as its tokens show it.
#[derive(Clone, Debug, PartialEq)]
pub enum SynType {
    /// A supported type whose element type and dimensions are visible.
    Known(KnownType),
    /// A type that is certainly not supported, with the advice to give.
    Unsupported(String),
    /// An alias or other path: only the compiler knows.
    Unknown,
}

const SUPPORTED: &str = "use bool, u8, u16, u32, u64, i8, i16, i32, i64, f32, f64, \
                         FixedString<N>, Time, or an array of these";

pub fn analyse(ty: &Type) -> SynType {
    match ty {
        Type::Paren(p) => analyse(&p.elem),
        Type::Group(g) => analyse(&g.elem),
        Type::Array(a) => {
            let len = match &a.len {
                Expr::Lit(l) => match &l.lit {
                    Lit::Int(i) => i.base10_parse::<u64>().ok(),
                    _ => None,
                },
                _ => None,
            };
            match (analyse(&a.elem), len) {
                (SynType::Known(mut k), Some(n)) => {
                    k.dims.insert(0, n);
                    SynType::Known(k)
                }
                (SynType::Unsupported(m), _) => SynType::Unsupported(m),
                _ => SynType::Unknown,
            }
        }
        Type::Path(p) if p.qself.is_none() => {
            let Some(last) = p.path.segments.last() else {
                return SynType::Unknown;
            };
            let name = last.ident.to_string();
            let single =
                p.path.segments.len() == 1 && matches!(last.arguments, PathArguments::None);
            if single && name != "FixedString" {
                if let Some(iec) = IecType::from_rust_name(&name) {
                    return SynType::Known(KnownType {
                        iec,
                        capacity: None,
                        dims: vec![],
                    });
                }
                return match name.as_str() {
                    "String" | "str" => SynType::Unsupported(format!(
                        "`{name}` has no fixed size: use plc_core::FixedString<N> with a capacity N of 1..=255 bytes"
                    )),
                    "char" => SynType::Unsupported(
                        "`char` is not a PLC type: use u8, or FixedString<4> for one character"
                            .into(),
                    ),
                    "usize" | "isize" => SynType::Unsupported(format!(
                        "`{name}` differs between machines: use a fixed-width integer such as {}",
                        if name == "usize" {
                            "u32 or u64"
                        } else {
                            "i32 or i64"
                        }
                    )),
                    "i128" | "u128" => SynType::Unsupported(format!(
                        "`{name}` has no IEC 61131-3 equivalent: use a 64-bit integer"
                    )),
                    _ => SynType::Unknown,
                };
            }
            if name == "FixedString" {
                return fixed_string(last);
            }
            if is_plc_core_time(&p.path) {
                return SynType::Known(KnownType::scalar(IecType::Ltime));
            }
            if matches!(
                name.as_str(),
                "Vec" | "Option" | "Box" | "HashMap" | "BTreeMap"
            ) {
                return SynType::Unsupported(format!(
                    "`{name}<..>` has no fixed layout in shared memory: {SUPPORTED}"
                ));
            }
            SynType::Unknown
        }
        Type::Tuple(_) => SynType::Unsupported(format!("a tuple is not a PLC type: {SUPPORTED}")),
        Type::Reference(_) | Type::Ptr(_) => SynType::Unsupported(format!(
            "references and pointers cannot live in shared memory: {SUPPORTED}"
        )),
        Type::Slice(_) => SynType::Unsupported(
            "a slice has no fixed size: use an array `[T; N]` (up to 3 dimensions)".into(),
        ),
        Type::FnPtr(_) | Type::TraitObject(_) | Type::ImplTrait(_) | Type::Never(_) => {
            SynType::Unsupported(format!("not a PLC type: {SUPPORTED}"))
        }
        _ => SynType::Unknown,
    }
}

/// `plc_core::Time` or `::plc_core::Time` (a bare `Time` is read as a Rust type name, as
/// `u16` is).
fn is_plc_core_time(path: &syn::Path) -> bool {
    let names: Vec<String> = path.segments.iter().map(|s| s.ident.to_string()).collect();
    names == ["plc_core", "Time"]
        && path
            .segments
            .iter()
            .all(|s| matches!(s.arguments, PathArguments::None))
}

fn fixed_string(segment: &syn::PathSegment) -> SynType {
    let PathArguments::AngleBracketed(args) = &segment.arguments else {
        return SynType::Unknown;
    };
    let capacity = args.args.iter().find_map(|a| match a {
        GenericArgument::Const(Expr::Lit(l)) => match &l.lit {
            Lit::Int(i) => i.base10_parse::<u64>().ok(),
            _ => None,
        },
        // `FixedString<64>` parses as a type argument in some syn versions? No: a literal is a
        // const argument. A named constant (`FixedString<LEN>`) is left to the compiler.
        _ => None,
    });
    match capacity {
        Some(n) => SynType::Known(KnownType {
            iec: IecType::String,
            capacity: Some(n),
            dims: vec![],
        }),
        None => SynType::Unknown,
    }
}

/// The type as written, compact: `[[f32; 4]; 3]`, `FixedString<64>`.
pub fn type_text(ty: &Type) -> String {
    let raw = quote::quote!(#ty).to_string();
    let mut out = String::with_capacity(raw.len());
    let mut chars = raw.chars().peekable();
    while let Some(c) = chars.next() {
        if c == ' ' {
            let prev = out.chars().last();
            let next = chars.peek().copied();
            let glue_prev = matches!(prev, Some('<' | '[' | '(' | ':' | '&'));
            let glue_next = matches!(next, Some('>' | ']' | ')' | ';' | ',' | '<' | ':'));
            if glue_prev || glue_next {
                continue;
            }
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn known(src: &str) -> KnownType {
        match analyse(&syn::parse_str(src).unwrap()) {
            SynType::Known(k) => k,
            other => panic!("{src}: {other:?}"),
        }
    }

    #[test]
    fn primitives_strings_and_arrays() {
        assert_eq!(known("u16").iec, IecType::Uint);
        let s = known("plc_core::FixedString<64>");
        assert_eq!((s.iec, s.capacity), (IecType::String, Some(64)));
        let a = known("[[f32; 4]; 3]");
        assert_eq!((a.iec, a.dims.clone()), (IecType::Real, vec![3, 4]));
        assert_eq!(analyse(&syn::parse_str("Word").unwrap()), SynType::Unknown);
        assert!(matches!(
            analyse(&syn::parse_str("String").unwrap()),
            SynType::Unsupported(_)
        ));
        assert!(matches!(
            analyse(&syn::parse_str("(u8, u8)").unwrap()),
            SynType::Unsupported(_)
        ));
    }

    #[test]
    fn time_in_plc_core_or_bare_is_ltime() {
        for src in ["Time", "plc_core::Time", "::plc_core::Time", "[Time; 3]"] {
            assert_eq!(known(src).iec, IecType::Ltime, "{src}");
        }
        for other in [
            "std::time::Duration",
            "chrono::Time",
            "plc_core::time::Time",
        ] {
            assert_eq!(
                analyse(&syn::parse_str(other).unwrap()),
                SynType::Unknown,
                "{other}"
            );
        }
    }

    #[test]
    fn type_text_is_compact() {
        let t = |s: &str| type_text(&syn::parse_str(s).unwrap());
        assert_eq!(t("[[f32; 4]; 3]"), "[[f32; 4]; 3]");
        assert_eq!(t("plc_core::FixedString<64>"), "plc_core::FixedString<64>");
        assert_eq!(t("u16"), "u16");
    }
}
