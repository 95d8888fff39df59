//! The `#[plc(...)]` attribute as written, one darling receiver per site. Validation beyond
//! syntax lives in `ast` (per field) and `check` (across fields).

use darling::util::SpannedValue;
use darling::{FromDeriveInput, FromField, FromMeta};

/// `#[plc(...)]` on the struct.
#[derive(FromDeriveInput)]
#[darling(attributes(plc))]
pub struct ContainerAttr {
    /// `crate = "path"`: where `plc_core` is, for re-exporting crates.
    #[darling(rename = "crate")]
    pub krate: Option<SpannedValue<syn::Path>>,
    /// `byte_order = "little"` for located variables (default big endian, IEC 61131-3 addressing).
    pub byte_order: Option<SpannedValue<String>>,
    /// `unaligned`: located W/D/L variables may sit at any byte offset.
    pub unaligned: Switch,
    /// `bus = "bus/machine.toml"`: check every link against this bus description.
    pub bus: Option<SpannedValue<String>>,
    /// `name = "Axis"` on a PlcStruct: its type name as tools show it (default: the struct's).
    pub name: Option<SpannedValue<String>>,
    /// plc-core's standard function blocks: members with IEC's own names (`IN`, `S`, `LD`),
    /// which users may not declare. Not for users.
    #[darling(rename = "__iec_standard")]
    pub iec_standard: Switch,
}

impl ContainerAttr {
    /// Reports the keys given on the wrong derive.
    pub fn only_on(&self, kind: crate::kind::Kind, cx: &mut crate::ctxt::Ctxt) {
        use crate::kind::Kind;
        let program_only = [
            ("byte_order", self.byte_order.as_ref().map(|v| v.span())),
            ("unaligned", self.unaligned.span()),
            ("bus", self.bus.as_ref().map(|v| v.span())),
        ];
        match kind {
            Kind::PlcStruct => {
                for (key, span) in program_only {
                    if let Some(span) = span {
                        cx.error(
                            span,
                            format!(
                                "`{key}` belongs on the `GlobalMemory` struct: a structure's \
                                 members have no physical I/O"
                            ),
                        );
                    }
                }
            }
            Kind::GlobalMemory => {
                if let Some(name) = &self.name {
                    cx.error(
                        name.span(),
                        "`name` names a `PlcStruct` type: a `GlobalMemory` struct's name is its \
                         segment's, given when the program starts",
                    );
                }
            }
        }
    }
}

/// `#[plc(...)]` on a field.
#[derive(FromField)]
#[darling(attributes(plc))]
pub struct FieldAttr {
    pub link: Option<SpannedValue<String>>,
    pub source: Option<SpannedValue<String>>,
    pub bit: Option<SpannedValue<i64>>,
    pub at: Option<SpannedValue<String>>,
    pub initial: Option<InitialExpr>,
    pub nonvolatile: Switch,
    pub retain: Switch,
    pub description: Option<SpannedValue<String>>,
    pub read_only: Switch,
    pub direction: Option<SpannedValue<String>>,
    pub name: Option<SpannedValue<String>>,
    pub iec_type: Option<SpannedValue<String>>,
    pub ux: Switch,
    pub quantity: Option<SpannedValue<String>>,
    pub unit: Option<SpannedValue<String>>,
    /// `deadband = 0.5`: the reporting deadband (not `alarm(deadband = ...)`).
    pub deadband: Option<SpannedValue<Deadband>>,
    pub alarm: Option<crate::alarm::AlarmAttr>,
    /// `alarm_when = false` beside `alarm = "..."`: an active-low bool.
    pub alarm_when: Option<SpannedValue<bool>>,
}

/// `initial = <literal>` kept as the expression written (darling would parse a string's
/// contents as an expression otherwise).
pub struct InitialExpr(pub syn::Expr);

impl FromMeta for InitialExpr {
    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        Ok(InitialExpr(expr.clone()))
    }
}

/// `deadband = 0.5`: a number as written, a negative one too (the declaration model refuses
/// it, in the words a variable list gets too).
pub struct Deadband(pub f64);

impl FromMeta for Deadband {
    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        let (negative, value) = match crate::alarm::literal(expr) {
            Some((negative, syn::Lit::Int(i))) => (negative, i.base10_parse::<f64>().ok()),
            Some((negative, syn::Lit::Float(f))) => (negative, f.base10_parse::<f64>().ok()),
            _ => (false, None),
        };
        match value.filter(|v| v.is_finite()) {
            Some(v) => Ok(Deadband(if negative { -v } else { v })),
            None => Err(darling::Error::custom(format!(
                "`deadband` takes {}",
                crate::symbol::expects("deadband").unwrap_or("a number")
            ))
            .with_span(expr)),
        }
    }
}

/// A key without a value (`nonvolatile`, `read_only`, `unaligned`). Unlike darling's `Flag`, a
/// value given by mistake (`nonvolatile = true`) gets a message that says how to write it.
#[derive(Default)]
pub struct Switch(Option<proc_macro2::Span>);

impl Switch {
    pub fn is_present(&self) -> bool {
        self.0.is_some()
    }

    pub fn span(&self) -> Option<proc_macro2::Span> {
        self.0
    }
}

impl FromMeta for Switch {
    fn from_none() -> Option<Self> {
        Some(Switch(None))
    }

    fn from_meta(item: &syn::Meta) -> darling::Result<Self> {
        match item {
            syn::Meta::Path(path) => Ok(Switch(Some(syn::spanned::Spanned::span(path)))),
            other => {
                let key = other
                    .path()
                    .get_ident()
                    .map_or_else(String::new, |i| i.to_string());
                Err(darling::Error::custom(format!(
                    "`{key}` is a flag and takes no value: write `{key}` alone (leave it out for \
                     the default)"
                ))
                .with_span(other))
            }
        }
    }
}
