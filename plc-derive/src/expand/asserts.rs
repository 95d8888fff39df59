//! Checks that need the real type of a field, for types the tokens do not show (aliases such
//! as `type Word = u16;`). Each is its own spanned `const` assertion so every one fires, with a
//! message computed here (a const panic cannot format values).

use super::private;
use crate::ast::{Container, Kind, Loc, Var};
use crate::types::SynType;
use plc_rules::address::Size;
use plc_rules::decl;
use proc_macro2::{Delimiter, Group, Span, TokenStream};
use quote::{quote, quote_spanned};

fn assert(span: Span, cond: TokenStream, message: String) -> TokenStream {
    quote_spanned!(span=> const _: () = ::core::assert!(#cond, #message);)
}

/// An assertion reported under all of `written` (e.g. both tokens of `-1`): the compiler spans
/// a macro call from its path to its closing delimiter, so the path takes the first token's span
/// and the arguments the last one's.
fn assert_over(written: &TokenStream, cond: TokenStream, message: String) -> TokenStream {
    let mut spans = written.clone().into_iter().map(|t| t.span());
    let first = spans.next().unwrap_or_else(Span::call_site);
    let last = spans.last().unwrap_or(first);
    let mut args = Group::new(Delimiter::Parenthesis, quote!(#cond, #message));
    args.set_span(last);
    let call = quote_spanned!(first=> ::core::assert!);
    quote_spanned!(first=> const _: () = #call #args;)
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let mut out = image_size(c);
    for (v, m) in c.fields() {
        let ty = v.ty;
        let name = v.field_name();
        if v.syn_type == SynType::Unknown {
            out.extend(assert(
                v.ty_span(),
                quote_spanned!(v.ty_span()=> #p::facts::<#ty>().shape_fits()),
                format!(
                    "the type of `{name}` must have at most 3 dimensions and 65535 items, and \
                     strings a capacity of 1..=255 bytes"
                ),
            ));
            out.extend(assert(
                v.ty_span(),
                quote_spanned!(v.ty_span()=> #p::facts::<#ty>().has_items()),
                format!(
                    "the type of `{name}` is an array without items: each dimension needs at \
                     least one item"
                ),
            ));
            structure_checks(c, v, m, &mut out);
            unknown_type_checks(c, v, m, &mut out);
            reporting_checks(c, v, m, &mut out);
        }
        // The bit must be within the source's width; only the compiler knows an alias's width.
        if let (Some((s, bit)), Some(b)) = (v.mapped_to, &m.bit) {
            let src = &c.vars[s];
            if src.syn_type == SynType::Unknown {
                let sty = src.ty;
                let at_source = m.source.as_ref().map_or(b.at.span(), |s| s.at.span());
                out.extend(assert(
                    at_source,
                    quote_spanned!(src.ty_span()=> #p::facts::<#sty>().is_integer()),
                    format!(
                        "the source `{}` must be an integer (u8, u16, u32, u64, i8, i16, i32 or \
                         i64), but its type is not",
                        src.field_name()
                    ),
                ));
                // A source that is not an integer is the one mistake; its bit is not judged.
                let facts = quote_spanned!(src.ty_span()=> #p::facts::<#sty>());
                out.extend(assert(
                    b.at.span(),
                    quote!(!#facts.is_integer() || (#bit as u32) < #facts.scalar_bits()),
                    format!(
                        "bit {bit} is out of range for the type of `{}`",
                        src.field_name()
                    ),
                ));
            }
        }
    }
    suppress_checks(c, &mut out);
    out
}

/// The whole image below 2^32 bytes: a structure's, and a program's.
fn image_size(c: &Container) -> TokenStream {
    let p = private(c);
    let what = match c.kind {
        Kind::GlobalMemory => "the variables",
        Kind::PlcStruct => "the members",
    };
    assert(
        c.ident.span(),
        quote!((#p::image_size(&__PLC_SIZES) as u64) < #p::plc_rules::capacity::MAX_IMAGE_BYTES),
        format!(
            "the image of `{}` is 4 GiB or more: {what} must take less than 2^32 bytes (fewer \
             or smaller array elements)",
            c.ident
        ),
    )
}

/// The rules for a field whose type is a structure (only the compiler knows): nesting depth,
/// and no physical I/O, `initial` or `nonvolatile` on the structure as a whole.
fn structure_checks(c: &Container, v: &Var, m: &decl::Var<Loc>, out: &mut TokenStream) {
    let p = private(c);
    let ty = v.ty;
    let name = v.field_name();
    let facts = quote_spanned!(v.ty_span()=> #p::facts::<#ty>());
    let max = plc_rules::capacity::MAX_STRUCT_DEPTH;
    // A member of a structure is one level further down than a program's field.
    let levels = match c.kind {
        Kind::GlobalMemory => max,
        Kind::PlcStruct => max - 1,
    };
    out.extend(assert(
        v.ty_span(),
        quote!(#facts.depth_at_most(#levels)),
        format!(
            "the type of `{name}` nests structures too deep: at most {max} levels of structures \
             in one another"
        ),
    ));
    if let Some(link) = &m.link {
        out.extend(assert(
            link.at.span(),
            quote!(!#facts.is_structured()),
            format!(
                "`{name}` is a structure: a link connects one basic variable to one entry; \
                 link a top-level variable of a basic type"
            ),
        ));
    }
    if let Some(init) = &v.initial {
        out.extend(assert_over(
            &init.tokens,
            quote!(!#facts.is_structured()),
            format!(
                "`{name}` is a structure: give `initial` on its members, in the structure's \
                 declaration"
            ),
        ));
    }
    if let Some(alarm) = &m.alarm {
        // The model's alarm rules need the type: for one only the compiler knows, these.
        let (cond, message) = if alarm.has_limits() {
            (
                quote!(#facts.has_number_elements()),
                format!(
                    "`{name}` must be a number for an alarm with limits (an alarm watches a \
                     bool, or a number against limits; a structure's alarms are declared on \
                     its members)"
                ),
            )
        } else {
            (
                quote!(#facts.has_bool_elements()),
                format!(
                    "`{name}` must be a bool (or an array of bools) for an alarm without \
                     limits (a structure's alarms are declared on its members)"
                ),
            )
        };
        out.extend(assert(alarm.at.span(), cond, message));
    }
    if let Some(span) = v.nonvolatile_at {
        out.extend(assert(
            span,
            quote!(!#facts.is_structured()),
            format!(
                "`{name}` is a structure: it cannot be `nonvolatile` as a whole; mark the members \
                 to keep `nonvolatile` in the structure's declaration"
            ),
        ));
    }
}

/// `unit` and `deadband` on a field whose type only the compiler knows (an alias, a
/// structure): the model could not tell whether it is a number. With an `iec_type` it could.
fn reporting_checks(c: &Container, v: &Var, m: &decl::Var<Loc>, out: &mut TokenStream) {
    if m.iec_type.is_some() {
        return;
    }
    let p = private(c);
    let ty = v.ty;
    let name = v.field_name();
    let given = [
        ("unit", m.unit.as_ref().map(|u| u.at.clone())),
        ("deadband", m.deadband.as_ref().map(|d| d.at.clone())),
    ];
    for (key, at) in given {
        let Some(at) = at else { continue };
        let message = format!(
            "`{key}` is for numbers (integers, REAL and LREAL, alone or in arrays): the type of \
             `{name}` is not one; remove `{key}` (a structure takes it on its members)"
        );
        let cond = quote_spanned!(v.ty_span()=> #p::facts::<#ty>().has_number_elements());
        out.extend(match &at {
            Loc::Tokens(written) => assert_over(written, cond, message),
            Loc::Span(span) => assert(*span, cond, message),
        });
    }
}

/// A `suppress_when` naming a field whose type only the compiler knows (an alias): the
/// model could not tell whether it is a bool.
fn suppress_checks(c: &Container, out: &mut TokenStream) {
    let p = private(c);
    for m in &c.decl.vars {
        let Some(s) = m.alarm.as_ref().and_then(|a| a.suppress_when.as_ref()) else {
            continue;
        };
        let path = s.value.trim();
        let target = c
            .decl
            .vars
            .iter()
            .position(|t| t.name.value.eq_ignore_ascii_case(path));
        let Some(t) = target
            .map(|j| &c.vars[j])
            .filter(|t| t.syn_type == SynType::Unknown)
        else {
            continue;
        };
        let ty = t.ty;
        out.extend(assert(
            s.at.span(),
            quote_spanned!(t.ty_span()=> #p::facts::<#ty>().is_bool()),
            format!(
                "`{path}` must be a bool: `suppress_when` names a bool that is true while the \
                 equipment is out of service"
            ),
        ));
    }
}

fn unknown_type_checks(c: &Container, v: &Var, m: &decl::Var<Loc>, out: &mut TokenStream) {
    let p = private(c);
    let ty = v.ty;
    let name = v.field_name();
    if v.mapped_to.is_some() {
        out.extend(assert(
            v.ty_span(),
            quote_spanned!(v.ty_span()=> #p::facts::<#ty>().is_bool()),
            format!("`{name}` is mapped to a bit, so its type must be bool"),
        ));
    }
    if let (Some(address), Some(at)) = (&v.address, &m.at) {
        let bits = address.size.bits();
        let text = at.value.as_str();
        let span = at.at.span();
        let facts = quote_spanned!(v.ty_span()=> #p::facts::<#ty>());
        // Two assertions, so an array or string is told it is no channel, not a wrong width.
        out.extend(assert(
            span,
            quote!(#facts.is_channel()),
            format!(
                "`at` locates one channel: the type of `{name}` must be a scalar, not an array \
                 or string (only internal variables have dimensions; no string \
                 channels)"
            ),
        ));
        let what = match address.size {
            Size::Bit => format!("a bit: the type of `{name}` must be bool"),
            _ => format!("{bits} bits wide: the type of `{name}` must have {bits} bits"),
        };
        out.extend(assert(
            span,
            quote!(!#facts.is_channel() || #facts.located_fits(#bits)),
            format!("`{text}` is {what}"),
        ));
    }
    if let Some(t) = &m.iec_type {
        let iec = super::metadata::iec_variant(c, t.value);
        out.extend(assert(
            t.at.span(),
            quote_spanned!(v.ty_span()=> #p::facts::<#ty>().storage_matches(#iec)),
            format!(
                "`iec_type = \"{}\"` does not fit the type of `{name}`: {} needs {}",
                t.value,
                t.value,
                t.value.rust_name()
            ),
        ));
    }
    if let Some(init) = &v.initial {
        // A structure's one error is the structure check's, not the kind of its value.
        let structured = quote_spanned!(v.ty_span()=> #p::facts::<#ty>().is_structured());
        for (cond, message) in init.alias_checks(&c.krate, ty, v.ty_span(), &name) {
            out.extend(assert_over(
                &init.tokens,
                quote!(#structured || (#cond)),
                message,
            ));
        }
    }
}
