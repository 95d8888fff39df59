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

fn opt_str(s: Option<&str>) -> TokenStream {
    match s {
        Some(s) => quote!(::core::option::Option::Some(#s)),
        None => quote!(::core::option::Option::None),
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

/// One `VarInfo` per field, in declaration order.
pub fn infos(c: &Container) -> Vec<TokenStream> {
    let p = private(c);
    let krate = &c.krate;
    c.fields()
        .enumerate()
        .map(|(i, (v, m))| {
            let ty = v.ty;
            let (offset, size) = (offset(i), size(i));
            let name = &m.name.value;
            let iec = iec_type(c, v, m);
            let rust_type = type_text(ty);
            let bit = match v.mapped_to {
                Some((s, b)) => quote!(::core::option::Option::Some(#p::bit_mapping(#s, #b))),
                None => quote!(::core::option::Option::None),
            };
            let link = opt_str(m.link.as_ref().map(|l| l.value.as_str()));
            let address = opt_str(
                m.at.as_ref()
                    .filter(|_| v.address.is_some())
                    .map(|a| a.value.as_str()),
            );
            let description = &m.description;
            let initial_json = v.initial.as_ref().map(|i| i.json());
            let initial = opt_str(initial_json.as_deref());
            let nonvolatile = m.nonvolatile;
            let access = if m.read_only {
                quote!(#krate::Access::ReadOnly)
            } else {
                quote!(#krate::Access::ReadWrite)
            };
            let dir = direction(c, v.effective_direction);
            let ux = m.ux;
            let quantity = opt_str(m.quantity.as_ref().map(|q| q.value.as_str()));
            quote! {
                #p::var_info(#p::VarInfoParts {
                    name: #name,
                    iec_type: #iec,
                    rust_type: #rust_type,
                    offset: #offset,
                    size: #size,
                    dims: <#ty as #p::PlcType>::DIMS,
                    bit: #bit,
                    link: #link,
                    address: #address,
                    description: #description,
                    initial: #initial,
                    nonvolatile: #nonvolatile,
                    access: #access,
                    direction: #dir,
                    ux: #ux,
                    quantity: #quantity,
                    members: <#ty as #p::PlcType>::MEMBERS,
                    type_name: <#ty as #p::PlcType>::TYPE_NAME,
                })
            }
        })
        .collect()
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let infos = infos(c);
    quote! {
        const VARIABLES: &'static [#krate::VarInfo] = &[#(#infos,)*];
        const LAYOUT_HASH: u64 = #p::layout_hash(Self::VARIABLES);
    }
}
