//! `ALARMS`: the table of declared alarms, flat, built by the compiler. Each field gives a
//! part: its own alarm (once per element of an array of bools), or, for a field whose type
//! only the compiler knows (a structure, an array of them), that type's table once per
//! element; `plc_core`'s `alarm_flatten` moves each copy to its instance's leaves. The
//! table's length is a `const` of the derive's block: an associated `const` could not name
//! it in a type.

use super::private;
use crate::ast::{Container, Kind};
use crate::types::SynType;
use plc_rules::decl::{self, Alarm, DEFAULT_SEVERITY, parse_delay};
use proc_macro2::{Literal, TokenStream};
use quote::{quote, quote_spanned};

/// The `const` items of the table (for the derive's `const _` block) and the associated
/// `const ALARMS` (for the `GlobalMemory` or `PlcType` impl); nothing if no field can have
/// alarms, so the trait's default (none) stands.
pub fn expand(c: &Container) -> (TokenStream, TokenStream) {
    let p = private(c);
    let krate = &c.krate;
    let parts: Vec<TokenStream> = c
        .fields()
        .enumerate()
        .filter_map(|(i, (v, m))| {
            let base = leaf_base(c, i);
            let facts = facts(c, i);
            if let Some(a) = &m.alarm {
                let template = template(c, a);
                return Some(quote! {
                    #p::AlarmPart {
                        index: #i,
                        base: #base,
                        table: &[#template],
                        elements: #facts.elements(),
                        stride: 1,
                        nested: false,
                    }
                });
            }
            (v.syn_type == SynType::Unknown).then(|| quote!(#facts.alarm_part(#i, #base)))
        })
        .collect();
    if parts.is_empty() {
        return (TokenStream::new(), TokenStream::new());
    }
    let bases = if c.kind == Kind::PlcStruct {
        // Each member's first leaf, summed once here: a sum per member would make the code
        // quadratic in the number of members.
        let n = c.vars.len();
        let leaves = (0..n).map(|j| facts(c, j));
        quote! {
            const __PLC_ALARM_BASES: [usize; #n] = {
                let leaves: [usize; #n] = [#(#leaves.leaves(),)*];
                let mut bases = [0usize; #n];
                let mut j = 1;
                while j < #n {
                    bases[j] = bases[j - 1] + leaves[j - 1];
                    j += 1;
                }
                bases
            };
        }
    } else {
        TokenStream::new()
    };
    let items = quote! {
        #bases
        const __PLC_ALARM_PARTS: &[#p::AlarmPart] = &[#(#parts,)*];
        const __PLC_ALARMS: [#p::AlarmDecl; #p::alarm_count(__PLC_ALARM_PARTS)] =
            #p::alarm_flatten(__PLC_ALARM_PARTS);
    };
    let assoc = quote! {
        const ALARMS: &'static [#krate::alarm::AlarmDecl] = &__PLC_ALARMS;
    };
    (items, assoc)
}

/// `facts::<T>()` of field `i`'s type, spanned at the type: if the type is no PLC type, the
/// error is the one its assertion gives (`asserts`), which the compiler reports once.
fn facts(c: &Container, i: usize) -> TokenStream {
    let p = private(c);
    let ty = c.vars[i].ty;
    quote_spanned!(c.vars[i].ty_span()=> #p::facts::<#ty>())
}

/// Member `i`'s first leaf in a structure (each member before it has its type's leaves); 0 for
/// a program's variable, whose leaves are its own.
fn leaf_base(c: &Container, i: usize) -> TokenStream {
    match c.kind {
        Kind::GlobalMemory => quote!(0),
        Kind::PlcStruct => quote!(__PLC_ALARM_BASES[#i]),
    }
}

/// A number as a literal of type `f64`, a negative one written with its `-`.
fn float(v: f64) -> TokenStream {
    let lit = Literal::f64_suffixed(v.abs());
    if v.is_sign_negative() {
        quote!(-#lit)
    } else {
        quote!(#lit)
    }
}

fn option(v: Option<f64>) -> TokenStream {
    match v {
        Some(v) => {
            let v = float(v);
            quote!(::core::option::Option::Some(#v))
        }
        None => quote!(::core::option::Option::None),
    }
}

/// One element's alarm, at leaf 0 of its field (`alarm_flatten` moves it).
fn template(c: &Container, a: &Alarm<crate::ast::Loc>) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let text = &a.text.value;
    let condition = if a.has_limits() {
        let [low_low, low, high, high_high] = a.limits.clone().map(|l| option(l.map(|l| l.value)));
        let deadband = float(a.deadband.as_ref().map_or(0.0, |d| d.value));
        quote!(#p::Condition::limit(#p::Limits {
            low_low: #low_low,
            low: #low,
            high: #high,
            high_high: #high_high,
            deadband: #deadband,
        }))
    } else {
        let active = a.when.as_ref().is_none_or(|w| w.value);
        quote!(#p::Condition::discrete(#active))
    };
    let mut out = quote!(#p::AlarmDecl::new(0, 0, #text, #condition));
    let severity = a.severity.as_ref().map_or(DEFAULT_SEVERITY, |s| s.value);
    if severity != DEFAULT_SEVERITY {
        // The checker kept it in 1..=1000.
        let severity = Literal::u16_unsuffixed(u16::try_from(severity).unwrap_or(500));
        out.extend(quote!(.with_severity(#severity)));
    }
    if let Some(Ok(delay)) = a.delay.as_ref().map(|d| parse_delay(&d.value))
        && delay.as_nanos() > 0
    {
        let ns = Literal::i64_unsuffixed(delay.as_nanos());
        out.extend(quote!(.with_delay(#krate::Time::from_nanos(#ns))));
    }
    if a.latched.is_some() {
        out.extend(quote!(.latched()));
    }
    if let Some(s) = &a.suppress_when {
        let target = suppress(c, &s.value);
        out.extend(quote!(.with_suppress(#target)));
    }
    out
}

/// Where the suppressing bool is: a variable (a member of the same structure) by index and
/// leaf, or a longer path resolved when the program starts.
fn suppress(c: &Container, path: &str) -> TokenStream {
    let p = private(c);
    let path = path.trim();
    let found = c
        .decl
        .vars
        .iter()
        .position(|v: &decl::Var<_>| v.name.value.eq_ignore_ascii_case(path));
    match found {
        Some(j) => {
            let leaf = leaf_base(c, j);
            quote!(#p::SuppressWhen::At { index: #j, leaf: #leaf })
        }
        None => quote!(#p::SuppressWhen::Path(#path)),
    }
}
