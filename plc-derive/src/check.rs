//! Checks that involve more than one field: names, bit mappings, addresses, directions, and
//! the fit of `initial` and `iec_type` to a type the tokens show. Each error points at the
//! attribute or type to change; where a second declaration clashes with a first, the message
//! names the first and its line.

use crate::ast::{At, Container, Dir, Var};
use crate::ctxt::{Ctxt, line_of};
use crate::types::SynType;
use plc_rules::IecType;
use plc_rules::address::{Area, Size};
use plc_rules::names;

pub fn check(c: &mut Container, cx: &mut Ctxt) {
    duplicate_names(c, cx);
    bit_mappings(c, cx);
    addresses(c, cx);
    directions(c, cx);
    initial_and_iec_type(c, cx);
}

fn duplicate_names(c: &Container, cx: &mut Ctxt) {
    for (i, v) in c.vars.iter().enumerate().filter(|(_, v)| v.name_known) {
        if let Some(first) = c.vars[..i]
            .iter()
            .filter(|w| w.name_known)
            .find(|w| names::same_name(&w.symbol.value, &v.symbol.value))
        {
            cx.error(
                v.symbol.span,
                format!(
                    "the variable name `{}` is already used by `{}`{}: names are \
                     case-insensitive (seed 003); rename one, e.g. with `#[plc(name = \"...\")]`",
                    v.symbol.value,
                    first.symbol.value,
                    line_of(first.symbol.span)
                ),
            );
        }
    }
}

/// Width in bits of a scalar integer type the tokens show.
fn integer_bits(v: &Var) -> Option<Result<u32, String>> {
    match &v.syn_type {
        SynType::Known(k) if k.is_scalar() && k.iec.is_integer() => Some(Ok(k.iec.bits())),
        SynType::Known(k) => Some(Err(if k.is_scalar() {
            k.element_name()
        } else {
            "an array".to_string()
        })),
        _ => None,
    }
}

fn bit_mappings(c: &mut Container, cx: &mut Ctxt) {
    let mut taken: Vec<(usize, i64, usize)> = Vec::new();
    for i in 0..c.vars.len() {
        let (Some(source), Some(bit)) = (c.vars[i].source.clone(), c.vars[i].bit.clone()) else {
            continue;
        };
        let me = c.vars[i].field_name();
        // Bit-mapped variables are bools (seed 000).
        if let SynType::Known(k) = &c.vars[i].syn_type
            && !(k.is_scalar() && k.iec == IecType::Bool)
        {
            cx.error(
                c.vars[i].ty_span(),
                format!(
                    "`{me}` is mapped to bit {} of `{}`, so its type must be bool (seed 000)",
                    bit.value, source.value
                ),
            );
        }
        let Some(s) = c.vars.iter().position(|w| w.field_name() == source.value) else {
            let hint = c
                .vars
                .iter()
                .find(|w| w.field_name().eq_ignore_ascii_case(&source.value))
                .map(|w| format!(" (did you mean `{}`?)", w.field_name()))
                .unwrap_or_default();
            cx.error(
                source.span,
                format!(
                    "`source = \"{}\"` names no field of this struct{hint}: name the integer \
                     field that holds the bit",
                    source.value
                ),
            );
            continue;
        };
        if s == i {
            cx.error(
                source.span,
                format!(
                    "`{me}` cannot be its own source: name the integer field that holds the bit"
                ),
            );
            continue;
        }
        match integer_bits(&c.vars[s]) {
            Some(Err(ty)) => {
                cx.error(
                    source.span,
                    format!(
                        "the source `{}` is {ty}, but a source must be an integer: u8, u16, u32, \
                         u64, i8, i16, i32 or i64 (seed 000)",
                        source.value
                    ),
                );
                continue;
            }
            Some(Ok(width)) if bit.value >= width as i64 => {
                let ty = c.vars[s].ty_text();
                cx.error(
                    bit.span,
                    format!(
                        "bit {} is out of range for `{}` ({ty} has bits 0..={})",
                        bit.value,
                        source.value,
                        width - 1
                    ),
                );
                continue;
            }
            _ => {}
        }
        if !(0..=63).contains(&bit.value) {
            continue;
        }
        if let Some(&(_, _, first)) = taken
            .iter()
            .find(|&&(ts, tb, _)| ts == s && tb == bit.value)
        {
            let first_name = c.vars[first].field_name();
            let first_line = line_of(c.vars[first].bit.as_ref().map_or(source.span, |b| b.span));
            cx.error(
                bit.span,
                format!(
                    "bit {} of `{}` is already mapped to `{first_name}`{first_line}: two bools \
                     cannot share a bit",
                    bit.value, source.value
                ),
            );
            continue;
        }
        taken.push((s, bit.value, i));
        c.vars[i].mapped_to = Some((s, bit.value as u8));
    }
}

/// The address size a type the tokens show needs.
fn size_for(v: &Var) -> Option<Result<Size, String>> {
    match &v.syn_type {
        SynType::Known(k) if !k.is_scalar() => Some(Err("an array".into())),
        SynType::Known(k) if k.iec == IecType::String => Some(Err(k.element_name())),
        SynType::Known(k) => Some(Size::from_bits(k.iec.bits()).ok_or_else(|| k.element_name())),
        _ => None,
    }
}

fn addresses(c: &Container, cx: &mut Ctxt) {
    let located: Vec<&Var> = c.vars.iter().filter(|v| v.at.is_some()).collect();
    for (n, v) in located.iter().enumerate() {
        let Some(at) = &v.at else { continue };
        let a = at.value;
        let text = v.at_text.as_deref().unwrap_or_default();
        match size_for(v) {
            Some(Err(what)) => {
                cx.error(
                    at.span,
                    format!(
                        "`{}` is {what}: `at` locates one I/O channel of a basic type (seed 003: \
                         only internal variables have dimensions; no string channels)",
                        v.field_name()
                    ),
                );
                continue;
            }
            Some(Ok(size)) if size != a.size => {
                cx.error(
                    at.span,
                    format!(
                        "`{text}` is {} but `{}` is {} ({}): write `%{}{}{}`",
                        size_phrase(a.size),
                        v.field_name(),
                        v.ty_text(),
                        bits_text(size.bits()),
                        a.area.letter(),
                        size.letter(),
                        if size == Size::Bit {
                            format!("{}.0", a.byte)
                        } else {
                            a.byte.to_string()
                        }
                    ),
                );
                continue;
            }
            _ => {}
        }
        if !c.unaligned && !a.is_aligned() {
            cx.error(
                at.span,
                format!(
                    "`{text}` is not aligned: a {} must start at a multiple of {} bytes (seed \
                     004); move it, or allow it with `#[plc(unaligned)]` on the struct",
                    size_name(a.size),
                    a.size.bytes()
                ),
            );
        }
        if let Some(first) = located[..n]
            .iter()
            .find(|w| w.at.as_ref().is_some_and(|wa| wa.value.overlaps(&a)))
        {
            let first_at = first.at.as_ref().map_or(at.span, |x| x.span);
            cx.error(
                at.span,
                format!(
                    "`{text}` overlaps `{}` of `{}`{}: each channel has its own bits",
                    first.at_text.as_deref().unwrap_or_default(),
                    first.field_name(),
                    line_of(first_at)
                ),
            );
        }
    }
}

/// "a bit", "an 8-bit byte", "a 16-bit word", ...
fn size_phrase(s: Size) -> String {
    match s {
        Size::Bit => "a bit".to_string(),
        Size::Byte => "an 8-bit byte".to_string(),
        other => format!("a {}-bit {}", other.bits(), size_name(other)),
    }
}

fn bits_text(bits: u32) -> String {
    if bits == 1 {
        "1 bit".into()
    } else {
        format!("{bits} bits")
    }
}

fn size_name(s: Size) -> &'static str {
    match s {
        Size::Bit => "bit",
        Size::Byte => "byte",
        Size::Word => "word",
        Size::DoubleWord => "double word",
        Size::LongWord => "long word",
    }
}

fn directions(c: &mut Container, cx: &mut Ctxt) {
    // Located and unmapped variables first; bit-mapped bools then take their source's.
    for v in c.vars.iter_mut() {
        let from_at = v.at.as_ref().map(|at| match at.value.area {
            Area::Input => Dir::Input,
            _ => Dir::Output,
        });
        v.effective_direction = match (&v.direction, from_at) {
            (Some(d), Some(implied)) if d.value != implied => {
                cx.error(
                    d.span,
                    format!(
                        "direction \"{}\" contradicts `at = \"{}\"`, which makes `{}` an {}: \
                         remove `direction` or change the address",
                        d.value.name(),
                        v.at_text.as_deref().unwrap_or_default(),
                        v.field_name(),
                        implied.name()
                    ),
                );
                implied
            }
            (Some(d), _) => d.value,
            (None, Some(implied)) => implied,
            (None, None) => Dir::Internal,
        };
    }
    for i in 0..c.vars.len() {
        let Some((s, _)) = c.vars[i].mapped_to else {
            continue;
        };
        let source_dir = c.vars[s].effective_direction;
        let v = &mut c.vars[i];
        match &v.direction {
            Some(At { value, span }) if *value != source_dir => cx.error(
                *span,
                format!(
                    "direction \"{}\" contradicts the source `{}`, which is {}: a bit-mapped \
                     bool takes its source's direction; remove `direction`",
                    value.name(),
                    v.source.as_ref().map_or("", |x| x.value.as_str()),
                    source_dir.name()
                ),
            ),
            _ => v.effective_direction = source_dir,
        }
    }
}

fn initial_and_iec_type(c: &Container, cx: &mut Ctxt) {
    for v in &c.vars {
        let SynType::Known(k) = &v.syn_type else {
            continue;
        };
        if let Some(t) = &v.iec_type
            && !t.value.same_storage(k.iec)
        {
            let hint = IecType::ALL
                .iter()
                .filter(|x| x.same_storage(k.iec))
                .map(|x| x.name())
                .collect::<Vec<_>>()
                .join(" or ");
            cx.error(
                t.span,
                format!(
                    "`iec_type = \"{}\"` does not fit `{}` ({}): {} is stored as {}; use {hint}, \
                     or change the field to {}",
                    t.value,
                    v.field_name(),
                    k.element_name(),
                    t.value,
                    t.value.rust_name(),
                    t.value.rust_name()
                ),
            );
        }
        if let Some(init) = &v.initial
            && let Some(msg) = init.misfit(k, &v.field_name())
        {
            cx.syn(syn::Error::new_spanned(&init.tokens, msg));
        }
    }
}

impl Var<'_> {
    pub fn ty_span(&self) -> proc_macro2::Span {
        syn::spanned::Spanned::span(self.ty)
    }

    pub fn ty_text(&self) -> String {
        crate::types::type_text(self.ty)
    }
}
