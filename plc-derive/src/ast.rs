//! The model of a `#[derive(GlobalMemory)]` struct: one `Var` per field with its attributes
//! parsed and validated on their own, each keeping the span of what the user wrote so later
//! errors can point at it (serde_derive's `ast`).

use crate::attr::{self, ContainerAttr, FieldAttr};
use crate::ctxt::Ctxt;
use crate::initial::Initial;
use crate::types::{self, SynType};
use darling::{FromDeriveInput, FromField};
use plc_rules::address::{Area, IecAddress};
use plc_rules::capacity::{MAX_ARRAY_DIMS, MAX_ARRAY_ITEMS, MAX_STRING_CAPACITY};
use plc_rules::{IecType, link::Link, names};
use proc_macro2::{Span, TokenStream};
use quote::quote;
use syn::spanned::Spanned;
use syn::{Data, DeriveInput, Fields, Ident, Type};

/// Where a variable's value comes from (mirrors `plc_core::Direction`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    Input,
    Output,
    Command,
    Status,
    Internal,
}

impl Dir {
    pub fn parse(s: &str) -> Option<Dir> {
        Some(match s {
            "input" => Dir::Input,
            "output" => Dir::Output,
            "command" => Dir::Command,
            "status" => Dir::Status,
            "internal" => Dir::Internal,
            _ => return None,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            Dir::Input => "input",
            Dir::Output => "output",
            Dir::Command => "command",
            Dir::Status => "status",
            Dir::Internal => "internal",
        }
    }
}

/// A value and the span of the tokens it came from.
#[derive(Clone, Debug)]
pub struct At<T> {
    pub value: T,
    pub span: Span,
}

pub struct Container<'a> {
    pub ident: &'a Ident,
    /// Path to `plc_core` (`crate = "..."` or `::plc_core`).
    pub krate: TokenStream,
    pub little_endian: bool,
    pub unaligned: bool,
    pub vars: Vec<Var<'a>>,
}

pub struct Var<'a> {
    pub ident: &'a Ident,
    pub ty: &'a Type,
    pub syn_type: SynType,
    /// Symbol name (`name = ".."` or the field name).
    pub symbol: At<String>,
    /// Whether `symbol` is surely the variable's name: not when the field's attribute did not
    /// parse and a `name = ".."` in it could not be read either. Name checks skip such a
    /// field rather than report a name the user may not have given it.
    pub name_known: bool,
    pub link: Option<At<String>>,
    pub source: Option<At<String>>,
    pub bit: Option<At<i64>>,
    pub at: Option<At<IecAddress>>,
    pub at_text: Option<String>,
    pub initial: Option<Initial>,
    pub nonvolatile: bool,
    pub description: String,
    pub read_only: bool,
    pub direction: Option<At<Dir>>,
    pub iec_type: Option<At<IecType>>,
    /// Filled in by `check`: index of the source variable of a bit-mapped bool.
    pub mapped_to: Option<(usize, u8)>,
    /// Filled in by `check`: the effective direction.
    pub effective_direction: Dir,
}

impl Var<'_> {
    /// The field name without `r#`.
    pub fn field_name(&self) -> String {
        let s = self.ident.to_string();
        s.strip_prefix("r#").map(str::to_string).unwrap_or(s)
    }
}

/// Parses the struct; every problem goes to `cx`. Returns `None` only when there is no struct
/// with named fields to model at all.
pub fn parse<'a>(input: &'a DeriveInput, cx: &mut Ctxt) -> Option<Container<'a>> {
    let fields = match &input.data {
        Data::Struct(s) => match &s.fields {
            Fields::Named(named) => Some(&named.named),
            Fields::Unnamed(f) => {
                cx.error(
                    f.span(),
                    "`GlobalMemory` needs named fields: each variable is known by its name \
                     (write `struct Gm { speed: i32 }`)",
                );
                None
            }
            Fields::Unit => {
                cx.error(
                    input.ident.span(),
                    "`GlobalMemory` needs a struct with named fields, one per variable",
                );
                None
            }
        },
        Data::Enum(e) => {
            cx.error(
                e.enum_token.span,
                "`GlobalMemory` cannot be derived for an enum: declare the variables as the \
                 named fields of a struct",
            );
            None
        }
        Data::Union(u) => {
            cx.error(
                u.union_token.span,
                "`GlobalMemory` cannot be derived for a union: declare the variables as the \
                 named fields of a struct",
            );
            None
        }
    };
    if !input.generics.params.is_empty() {
        cx.error(
            input.generics.span(),
            "`GlobalMemory` cannot be derived for a generic struct: the shared-memory layout \
             must be fixed; remove the type, lifetime and const parameters",
        );
    }
    let container = match ContainerAttr::from_derive_input(input) {
        Ok(c) => Some(c),
        Err(e) => {
            cx.darling(e);
            None
        }
    };
    let fields = fields?;
    let mut krate = quote!(::plc_core);
    let mut little_endian = false;
    let mut unaligned = false;
    if let Some(c) = container {
        if let Some(path) = c.krate {
            let path = path.as_ref();
            krate = quote!(#path);
        }
        if let Some(order) = c.byte_order {
            match order.as_str() {
                "little" => little_endian = true,
                "big" => {}
                other => cx.error(
                    order.span(),
                    format!(
                        "unknown byte order `{other}`: write `byte_order = \"little\"` or \
                         `\"big\"` (the default, as seed 004)"
                    ),
                ),
            }
        }
        unaligned = c.unaligned.is_present();
    }
    // Named fields always have an identifier; `filter_map` keeps that a fact, not a panic.
    let vars = fields
        .iter()
        .filter_map(|f| f.ident.as_ref().map(|ident| parse_field(f, ident, cx)))
        .collect();
    Some(Container {
        ident: &input.ident,
        krate,
        little_endian,
        unaligned,
        vars,
    })
}

fn parse_field<'a>(field: &'a syn::Field, ident: &'a Ident, cx: &mut Ctxt) -> Var<'a> {
    let attr = match FieldAttr::from_field(field) {
        Ok(a) => Some(a),
        Err(e) => {
            cx.darling(e);
            None
        }
    };
    let syn_type = types::analyse(&field.ty);
    check_type(&field.ty, &syn_type, cx);
    let field_name = {
        let s = ident.to_string();
        s.strip_prefix("r#").map(str::to_string).unwrap_or(s)
    };
    let mut var = Var {
        ident,
        ty: &field.ty,
        syn_type,
        symbol: At {
            value: field_name.clone(),
            span: ident.span(),
        },
        name_known: true,
        link: None,
        source: None,
        bit: None,
        at: None,
        at_text: None,
        initial: None,
        nonvolatile: false,
        description: doc_description(&field.attrs),
        read_only: false,
        direction: None,
        iec_type: None,
        mapped_to: None,
        effective_direction: Dir::Internal,
    };
    match attr {
        Some(a) => fill_from_attr(&mut var, a, &field.attrs, cx),
        None => match recover_name(&field.attrs) {
            Some(Some(name)) => var.symbol = name,
            Some(None) => {}
            None => var.name_known = false,
        },
    }
    if var.name_known
        && let Err(e) = names::check_name(&var.symbol.value)
    {
        cx.error(
            var.symbol.span,
            format!(
                "invalid variable name `{}`: {e} (seed 003)",
                var.symbol.value
            ),
        );
    }
    var
}

/// After darling refused a field's attribute (its error is reported), the `name = ".."` the
/// attribute may still hold, so that a field `end` renamed `EndPos` is not also reported as
/// a keyword: `Some(Some(name))`, `Some(None)` if it has no name, `None` if the attribute does
/// not parse far enough to tell.
fn recover_name(attrs: &[syn::Attribute]) -> Option<Option<At<String>>> {
    let mut name = None;
    for attr in attrs.iter().filter(|a| a.path().is_ident("plc")) {
        attr.parse_nested_meta(|meta| {
            if meta.input.peek(syn::Token![=]) {
                let value = meta.value()?;
                if meta.path.is_ident("name") {
                    let lit: syn::LitStr = value.parse()?;
                    name = Some(At {
                        value: lit.value(),
                        span: lit.span(),
                    });
                } else {
                    value.parse::<syn::Expr>()?;
                }
            } else if meta.input.peek(syn::token::Paren) {
                meta.input.parse::<proc_macro2::Group>()?;
            }
            Ok(())
        })
        .ok()?;
    }
    Some(name)
}

fn fill_from_attr(var: &mut Var, a: FieldAttr, attrs: &[syn::Attribute], cx: &mut Ctxt) {
    if let Some(name) = a.name {
        var.symbol = At {
            value: name.to_string(),
            span: name.span(),
        };
    }
    if let Some(link) = a.link {
        if let Err(e) = Link::parse(&link) {
            cx.error(
                link.span(),
                format!("invalid link `{}`: {e}", link.as_str()),
            );
        }
        var.link = Some(At {
            value: link.to_string(),
            span: link.span(),
        });
    }
    match (&a.source, &a.bit) {
        (Some(s), None) => cx.error(
            s.span(),
            "`source` needs `bit`: add `bit = N`, the bit of the source word (0 = least \
             significant) that this bool maps to",
        ),
        (None, Some(b)) => cx.error(
            b.span(),
            "`bit` needs `source`: add `source = \"<field>\"`, the integer field that holds \
             this bit",
        ),
        _ => {}
    }
    if let Some(b) = &a.bit
        && !(0..=63).contains(&**b)
    {
        let message = format!(
            "bit {} is out of range: bits are 0..=63 (0 = least significant)",
            **b
        );
        match attr::raw_value(attrs, "bit") {
            Some(written) => cx.syn(syn::Error::new_spanned(written, message)),
            None => cx.error(b.span(), message),
        }
    }
    var.source = a.source.map(|s| At {
        value: s.to_string(),
        span: s.span(),
    });
    var.bit = a.bit.map(|b| At {
        value: *b,
        span: b.span(),
    });
    if let Some(at) = a.at {
        match at.parse::<IecAddress>() {
            Ok(address) if address.area == Area::Memory => cx.error(
                at.span(),
                format!(
                    "`at = \"{}\"` is in the M area: `at` locates I/O channels, so use %I \
                     (input) or %Q (output); internal variables need no address (seed 003)",
                    at.as_str()
                ),
            ),
            Ok(address) => {
                var.at = Some(At {
                    value: address,
                    span: at.span(),
                });
                var.at_text = Some(at.to_string());
            }
            Err(e) => cx.error(at.span(), format!("invalid address {e}")),
        }
    }
    if let Some(init) = a.initial {
        let expr = &init.0;
        let written = attr::raw_value(attrs, "initial").unwrap_or_else(|| quote!(#expr));
        match Initial::parse(expr, written) {
            Ok(i) => var.initial = Some(i),
            Err(e) => cx.syn(e),
        }
    }
    if let (Some(_), Some(retain)) = (a.nonvolatile.span(), a.retain.span()) {
        cx.error(
            retain,
            "`retain` is another name for `nonvolatile`: write only one of them",
        );
    }
    var.nonvolatile = a.nonvolatile.is_present() || a.retain.is_present();
    if let Some(d) = a.description {
        var.description = d.trim().to_string();
    }
    var.read_only = a.read_only.is_present();
    if let Some(d) = a.direction {
        match Dir::parse(&d) {
            Some(dir) => {
                var.direction = Some(At {
                    value: dir,
                    span: d.span(),
                })
            }
            None => cx.error(
                d.span(),
                format!(
                    "unknown direction `{}`: use \"input\", \"output\", \"command\", \"status\" \
                     or \"internal\"",
                    d.as_str()
                ),
            ),
        }
    }
    if let Some(t) = a.iec_type {
        match t.parse::<IecType>() {
            Ok(iec) => {
                var.iec_type = Some(At {
                    value: iec,
                    span: t.span(),
                })
            }
            Err(_) => cx.error(
                t.span(),
                format!(
                    "unknown IEC type `{}`: use BYTE, WORD, DWORD or LWORD for a bit string, or \
                     an elementary type such as UINT",
                    t.as_str()
                ),
            ),
        }
    }
}

/// Checks what the type's tokens alone show.
fn check_type(ty: &Type, syn_type: &SynType, cx: &mut Ctxt) {
    match syn_type {
        SynType::Unsupported(message) => cx.error(ty.span(), message),
        SynType::Known(k) => {
            if let Some(n) = k.capacity
                && (n == 0 || n > MAX_STRING_CAPACITY as u64)
            {
                cx.error(
                    ty.span(),
                    format!(
                        "a string capacity must be 1..=255 bytes, not {n} (seed 000 \
                         `max_length`, seed 003)"
                    ),
                );
            }
            if k.dims.len() > MAX_ARRAY_DIMS {
                cx.error(
                    ty.span(),
                    format!(
                        "an array has at most {MAX_ARRAY_DIMS} dimensions, this one has {} \
                         (seed 003)",
                        k.dims.len()
                    ),
                );
            }
            let items = k.dims.iter().try_fold(1u64, |a, &d| a.checked_mul(d));
            if items.is_none_or(|n| n > MAX_ARRAY_ITEMS as u64) {
                cx.error(
                    ty.span(),
                    format!(
                        "an array holds at most {MAX_ARRAY_ITEMS} items in all dimensions, this \
                         one holds {} (seed 003)",
                        items.map_or("more than 2^64".to_string(), |n| n.to_string())
                    ),
                );
            }
            if k.dims.contains(&0) {
                cx.error(
                    ty.span(),
                    "an array needs at least one item in each dimension",
                );
            }
        }
        SynType::Unknown => {}
    }
}

/// The doc comment as a description: each line trimmed, blank lines dropped, joined by a space.
fn doc_description(attrs: &[syn::Attribute]) -> String {
    let mut lines = Vec::new();
    for attr in attrs {
        if !attr.path().is_ident("doc") {
            continue;
        }
        if let syn::Meta::NameValue(nv) = &attr.meta
            && let syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Str(s),
                ..
            }) = &nv.value
        {
            for line in s.value().lines() {
                let line = line.trim();
                if !line.is_empty() {
                    lines.push(line.to_string());
                }
            }
        }
    }
    lines.join(" ")
}
