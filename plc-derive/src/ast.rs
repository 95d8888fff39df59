//! The model of a `#[derive(GlobalMemory)]` or `#[derive(PlcStruct)]` struct: each field's
//! attributes parsed into the
//! declaration model (`plc_rules::decl`), each keeping the span of what the user wrote so the
//! checker's issues point at it, beside what only the Rust code has (serde_derive's `ast`).

use crate::attr::{ContainerAttr, FieldAttr};
use crate::ctxt::Ctxt;
use crate::initial::Initial;
pub use crate::kind::Kind;
pub use crate::loc::{At, Loc};
use crate::types::{self, SynType};
use darling::util::SpannedValue;
use darling::{FromDeriveInput, FromField};
use plc_rules::IecType;
use plc_rules::address::IecAddress;
use plc_rules::decl::{self, Decl, DeclType, Direction, Issue, IssueKind, Located};
use proc_macro2::{Span, TokenStream};
use quote::quote;
use syn::spanned::Spanned;
use syn::{Data, DeriveInput, Fields, Ident, Type};

pub struct Container<'a> {
    pub kind: Kind,
    pub ident: &'a Ident,
    /// The structure's type name (`#[plc(name = "...")]` or the struct's name), as tools show
    /// it.
    pub type_name: String,
    /// Path to `plc_core` (`crate = "..."` or `::plc_core`).
    pub krate: TokenStream,
    pub little_endian: bool,
    pub vars: Vec<Var<'a>>,
    /// The declaration model of the struct, one variable per field, that `check` applies the
    /// rules to.
    pub decl: Decl<Loc>,
    /// `bus = "..."`: the bus description the links are checked against.
    pub bus: Option<At<String>>,
}

impl Container<'_> {
    /// Each field with its model.
    pub fn fields(&self) -> impl Iterator<Item = (&Var<'_>, &decl::Var<Loc>)> {
        self.vars.iter().zip(&self.decl.vars)
    }
}

/// A field: what only the Rust code has (its ident, type tokens, the literal's tokens), its
/// model (`Container::decl`, same index), and what the checker resolved.
pub struct Var<'a> {
    pub ident: &'a Ident,
    pub ty: &'a Type,
    pub syn_type: SynType,
    pub initial: Option<Initial>,
    /// Filled in by `check`: index of the source variable of a bit-mapped bool, and the bit.
    pub mapped_to: Option<(usize, u8)>,
    /// Filled in by `check`: the effective direction.
    pub effective_direction: Direction,
    /// Filled in by `check`: the valid I/O address of `at`.
    pub address: Option<IecAddress>,
    /// Where `nonvolatile` (or `retain`) was written.
    pub nonvolatile_at: Option<Span>,
}

impl Var<'_> {
    /// The field name without `r#`.
    pub fn field_name(&self) -> String {
        field_name(self.ident)
    }

    pub fn ty_span(&self) -> Span {
        self.ty.span()
    }
}

fn field_name(ident: &Ident) -> String {
    let s = ident.to_string();
    s.strip_prefix("r#").map(str::to_string).unwrap_or(s)
}

/// Parses the struct; every problem goes to `cx`. Returns `None` only when there is no struct
/// with named fields to model at all.
pub fn parse<'a>(input: &'a DeriveInput, kind: Kind, cx: &mut Ctxt) -> Option<Container<'a>> {
    let (derive, field) = (kind.name(), kind.field());
    let fields = match &input.data {
        Data::Struct(s) => match &s.fields {
            Fields::Named(named) => Some(&named.named),
            Fields::Unnamed(f) => {
                cx.error(
                    f.span(),
                    format!(
                        "`{derive}` needs named fields: each {field} is known by its name \
                         (write `{}`)",
                        kind.example()
                    ),
                );
                None
            }
            Fields::Unit => {
                cx.error(
                    input.ident.span(),
                    format!("`{derive}` needs a struct with named fields, one per {field}"),
                );
                None
            }
        },
        Data::Enum(e) => {
            cx.error(
                e.enum_token.span,
                format!(
                    "`{derive}` cannot be derived for an enum: declare the {field}s as the \
                     named fields of a struct"
                ),
            );
            None
        }
        Data::Union(u) => {
            cx.error(
                u.union_token.span,
                format!(
                    "`{derive}` cannot be derived for a union: declare the {field}s as the \
                     named fields of a struct"
                ),
            );
            None
        }
    };
    if !input.generics.params.is_empty() {
        cx.error(
            input.generics.span(),
            format!(
                "`{derive}` cannot be derived for a generic struct: the shared-memory layout \
                 must be fixed; remove the type, lifetime and const parameters"
            ),
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
    let mut bus = None;
    let mut type_name = input.ident.to_string();
    let mut standard_names = false;
    if let Some(c) = container {
        c.only_on(kind, cx);
        if let Some(name) = &c.name {
            type_name = name.to_string();
        }
        standard_names = c.iec_standard.is_present();
        bus = c
            .bus
            .as_ref()
            .map(|b| At::new(b.to_string(), Loc::Span(b.span())));
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
                         `\"big\"` (the default: IEC 61131-3 process images are big endian)"
                    ),
                ),
            }
        }
        unaligned = c.unaligned.is_present();
    }
    // Named fields always have an identifier; `filter_map` keeps that a fact, not a panic.
    let (vars, decl_vars) = fields
        .iter()
        .filter_map(|f| f.ident.as_ref().map(|ident| parse_field(f, ident, cx)))
        .unzip();
    let mut decl_vars: Vec<decl::Var<Loc>> = decl_vars;
    if standard_names {
        // plc-core's standard function blocks carry IEC's member names (`IN`, `S`, `LD`),
        // which the naming rules keep from users.
        for v in &mut decl_vars {
            v.name_known = false;
        }
    }
    Some(Container {
        kind,
        type_name,
        ident: &input.ident,
        krate,
        little_endian,
        vars,
        decl: Decl {
            vars: decl_vars,
            unaligned,
            structure: kind == Kind::PlcStruct,
        },
        bus,
    })
}

fn parse_field<'a>(
    field: &'a syn::Field,
    ident: &'a Ident,
    cx: &mut Ctxt,
) -> (Var<'a>, decl::Var<Loc>) {
    let attr = match FieldAttr::from_field(field) {
        Ok(a) => Some(a),
        Err(e) => {
            cx.darling(e);
            None
        }
    };
    let syn_type = types::analyse(&field.ty);
    if let SynType::Unsupported(message) = &syn_type {
        cx.error(field.ty.span(), message);
    }
    let name = field_name(ident);
    let ty = match &syn_type {
        SynType::Known(k) => DeclType::Known(k.clone()),
        _ => DeclType::Unknown,
    };
    let mut model = decl::Var::new(
        Located::new(name.clone(), Loc::Span(ident.span())),
        &name,
        Located::new(ty, Loc::Span(field.ty.span())),
    );
    model.description = doc_description(&field.attrs);
    let mut var = Var {
        ident,
        ty: &field.ty,
        syn_type,
        initial: None,
        mapped_to: None,
        effective_direction: Direction::Internal,
        address: None,
        nonvolatile_at: None,
    };
    match attr {
        Some(a) => fill_from_attr(&mut var, &mut model, a, &field.attrs, cx),
        None => match recover_name(&field.attrs) {
            Some(Some(name)) => model.name = name,
            Some(None) => {}
            None => model.name_known = false,
        },
    }
    (var, model)
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
                    name = Some(At::new(lit.value(), Loc::Span(lit.span())));
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

fn fill_from_attr(
    var: &mut Var,
    model: &mut decl::Var<Loc>,
    a: FieldAttr,
    attrs: &[syn::Attribute],
    cx: &mut Ctxt,
) {
    let at = |v: &SpannedValue<String>| At::new(v.to_string(), Loc::Span(v.span()));
    if let Some(name) = &a.name {
        model.name = at(name);
    }
    model.link = a.link.as_ref().map(at);
    model.source = a.source.as_ref().map(at);
    model.bit = a.bit.map(|b| {
        // The whole of `-1`, not only its `-`.
        let loc =
            crate::raw_value::raw_value(attrs, "bit").map_or(Loc::Span(b.span()), Loc::Tokens);
        At::new(*b, loc)
    });
    model.at = a.at.as_ref().map(at);
    if let Some(init) = a.initial {
        let expr = &init.0;
        let written =
            crate::raw_value::raw_value(attrs, "initial").unwrap_or_else(|| quote!(#expr));
        match Initial::parse(expr, written) {
            Ok(i) => {
                model.initial = Some(At::new(i.to_decl(), Loc::Tokens(i.tokens.clone())));
                var.initial = Some(i);
            }
            Err(e) => cx.syn(e),
        }
    }
    if let (Some(_), Some(retain)) = (a.nonvolatile.span(), a.retain.span()) {
        cx.error(
            retain,
            "`retain` is another name for `nonvolatile`: write only one of them",
        );
    }
    model.nonvolatile = a.nonvolatile.is_present() || a.retain.is_present();
    var.nonvolatile_at = a.nonvolatile.span().or(a.retain.span());
    if let Some(d) = a.description {
        model.description = d.trim().to_string();
    }
    model.read_only = a.read_only.is_present();
    model.ux = a.ux.is_present();
    model.quantity = a.quantity.as_ref().map(at);
    model.unit = a.unit.as_ref().map(at);
    model.deadband = a.deadband.map(|d| {
        // The whole of `-0.5`, not only its `-`.
        let loc =
            crate::raw_value::raw_value(attrs, "deadband").map_or(Loc::Span(d.span()), Loc::Tokens);
        At::new(d.as_ref().0, loc)
    });
    model.alarm = a.alarm.map(|x| x.0);
    if let Some(w) = a.alarm_when {
        let when = At::new(*w, Loc::Span(w.span()));
        match &mut model.alarm {
            None => cx.error(
                w.span(),
                "`alarm_when` says when an alarm is active: declare one with `alarm = \"...\"`",
            ),
            Some(alarm) if alarm.when.is_some() => cx.error(
                w.span(),
                "`alarm_when` is given twice, beside `alarm(...)` and in it: keep one",
            ),
            Some(alarm) => alarm.when = Some(when),
        }
    }
    if let Some(d) = a.direction {
        match Direction::from_name(&d) {
            Some(dir) => model.direction = Some(At::new(dir, Loc::Span(d.span()))),
            None => cx.issue(&Issue::new(
                IssueKind::UnknownDirection {
                    text: d.to_string(),
                },
                Loc::Span(d.span()),
            )),
        }
    }
    if let Some(t) = a.iec_type {
        match t.parse::<IecType>() {
            Ok(iec) => model.iec_type = Some(At::new(iec, Loc::Span(t.span()))),
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
