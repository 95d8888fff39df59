//! `VARIABLES` and `LAYOUT_HASH`: what tools read about each variable.

use super::image::{offset, size};
use super::private;
use crate::ast::{Container, Dir, Var};
use crate::types::type_text;
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
pub fn iec_type(c: &Container, v: &Var) -> TokenStream {
    let p = private(c);
    let ty = v.ty;
    match &v.iec_type {
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

fn direction(c: &Container, d: Dir) -> TokenStream {
    let krate = &c.krate;
    let variant = format_ident!(
        "{}",
        match d {
            Dir::Input => "Input",
            Dir::Output => "Output",
            Dir::Command => "Command",
            Dir::Status => "Status",
            Dir::Internal => "Internal",
        }
    );
    quote!(#krate::Direction::#variant)
}

pub fn expand(c: &Container) -> TokenStream {
    let p = private(c);
    let krate = &c.krate;
    let infos = c.vars.iter().enumerate().map(|(i, v)| {
        let ty = v.ty;
        let (offset, size) = (offset(i), size(i));
        let name = &v.symbol.value;
        let iec = iec_type(c, v);
        let rust_type = type_text(ty);
        let bit = match v.mapped_to {
            Some((s, b)) => quote!(::core::option::Option::Some(#p::bit_mapping(#s, #b))),
            None => quote!(::core::option::Option::None),
        };
        let link = opt_str(v.link.as_ref().map(|l| l.value.as_str()));
        let address = opt_str(v.at_text.as_deref());
        let description = &v.description;
        let initial_json = v.initial.as_ref().map(|i| i.json());
        let initial = opt_str(initial_json.as_deref());
        let nonvolatile = v.nonvolatile;
        let access = if v.read_only {
            quote!(#krate::Access::ReadOnly)
        } else {
            quote!(#krate::Access::ReadWrite)
        };
        let dir = direction(c, v.effective_direction);
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
            })
        }
    });
    quote! {
        const VARIABLES: &'static [#krate::VarInfo] = &[#(#infos,)*];
        const LAYOUT_HASH: u64 = #p::layout_hash(Self::VARIABLES);
    }
}
