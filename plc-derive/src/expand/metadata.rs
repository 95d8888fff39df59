//! `VARIABLES` and `LAYOUT_HASH`: what tools read about each variable.

use super::image::{offset, size};
use super::private;
use crate::ast::{Container, Loc, Var};
use crate::types::type_text;
use plc_rules::Direction;
use plc_rules::decl;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// `IecType::Word` from `WORD`.
pub fn iec_variant(c: &Container, iec: plc_rules::IecType) -> TokenStream {
    let krate = &c.krate;
    let name = iec.name();
    let variant = format_ident!("{}{}", &name[..1], name[1..].to_ascii_lowercase());
    quote!(#krate::IecType::#variant)
}

/// The variable's IEC type: the declared `iec_type`, else what its Rust type maps to.
pub fn iec_type(c: &Container, v: &Var, m: &decl::Var<Loc>) -> TokenStream {
    let p = private(c);
    let ty = v.ty;
    match &m.iec_type {
        Some(t) => iec_variant(c, t.value),
        None => quote!(<#ty as #p::PlcType>::IEC_TYPE),
    }
}

fn direction(c: &Container, d: Direction) -> TokenStream {
    let krate = &c.krate;
    let variant = format_ident!(
        "{}",
        match d {
            Direction::Input => "Input",
            Direction::Output => "Output",
            Direction::Command => "Command",
            Direction::Status => "Status",
            Direction::Internal => "Internal",
        }
    );
    quote!(#krate::Direction::#variant)
}

/// One `VarInfo` per field, in declaration order: each a call of `var` with the type, name
/// and place, then a setter for each attribute the field declares (a literal of every part
/// per field made a 10,000-variable declaration cost the compiler twice the time and memory).
pub fn infos(c: &Container) -> Vec<TokenStream> {
    let p = private(c);
    c.fields()
        .enumerate()
        .map(|(i, (v, m))| {
            let ty = v.ty;
            let (offset, size) = (offset(i), size(i));
            let name = &m.name.value;
            let rust_type = type_text(ty);
            let mut setters = TokenStream::new();
            if let Some(t) = &m.iec_type {
                let iec = iec_variant(c, t.value);
                setters.extend(quote!(.iec(#iec)));
            }
            if let Some((s, b)) = v.mapped_to {
                setters.extend(quote!(.bit(#s, #b)));
            }
            if let Some(link) = &m.link {
                let link = &link.value;
                setters.extend(quote!(.link(#link)));
            }
            if let (Some(at), Some(_)) = (&m.at, &v.address) {
                let at = &at.value;
                setters.extend(quote!(.address(#at)));
            }
            if !m.description.is_empty() {
                let description = &m.description;
                setters.extend(quote!(.description(#description)));
            }
            if let Some(json) = v.initial.as_ref().map(|i| i.json()) {
                setters.extend(quote!(.initial(#json)));
            }
            if m.nonvolatile {
                setters.extend(quote!(.nonvolatile()));
            }
            if m.read_only {
                setters.extend(quote!(.read_only()));
            }
            if v.effective_direction != Direction::Internal {
                let dir = direction(c, v.effective_direction);
                setters.extend(quote!(.direction(#dir)));
            }
            if m.ux {
                setters.extend(quote!(.ux()));
            }
            if let Some(q) = &m.quantity {
                let q = &q.value;
                setters.extend(quote!(.quantity(#q)));
            }
            if let Some(u) = &m.unit {
                let u = &u.value;
                setters.extend(quote!(.unit(#u)));
            }
            if let Some(d) = &m.deadband {
                let d = d.value;
                setters.extend(quote!(.deadband(#d)));
            }
            quote!(#p::var::<#ty>(#name, #rust_type, #offset, #size) #setters)
        })
        .collect()
}

/// Variables per `const` of the layout hash: one evaluation over 100,000 variables ran into
/// the compiler's guard against endless const evaluation.
const HASH_PART: usize = 1024;

/// For a declaration of more than [`HASH_PART`] variables, the `const`s of the layout hash's
/// parts (`__PLC_HASH_k`: the hasher after part `k`), for the inherent impl; else nothing.
pub fn hash_parts(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let n = c.vars.len();
    if n <= HASH_PART {
        return TokenStream::new();
    }
    let mut out = TokenStream::new();
    for (k, start) in (0..n).step_by(HASH_PART).enumerate() {
        let end = (start + HASH_PART).min(n);
        let name = format_ident!("__PLC_HASH_{k}");
        let before = match k {
            0 => quote!(#p::plc_rules::layout::LayoutHasher::new()),
            _ => {
                let prev = format_ident!("__PLC_HASH_{}", k - 1);
                quote!(Self::#prev)
            }
        };
        out.extend(quote! {
            const #name: #p::plc_rules::layout::LayoutHasher = #p::hash_range(
                #before,
                <Self as #krate::GlobalMemory>::VARIABLES,
                #start,
                #end,
            );
        });
    }
    out
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let infos = infos(c);
    let n = c.vars.len();
    let hash = if n <= HASH_PART {
        quote!(#p::layout_hash(Self::VARIABLES))
    } else {
        let last = format_ident!("__PLC_HASH_{}", n.div_ceil(HASH_PART) - 1);
        quote!(Self::#last.finish())
    };
    quote! {
        const VARIABLES: &'static [#krate::VarInfo] = &[#(#infos,)*];
        const LAYOUT_HASH: u64 = #hash;
    }
}
