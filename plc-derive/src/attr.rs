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
    /// `byte_order = "little"` for located variables (default big endian, seed 004).
    pub byte_order: Option<SpannedValue<String>>,
    /// `unaligned`: located W/D/L variables may sit at any byte offset.
    pub unaligned: Switch,
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
}

/// `initial = <literal>` kept as the expression written (darling would parse a string's
/// contents as an expression otherwise).
pub struct InitialExpr(pub syn::Expr);

impl FromMeta for InitialExpr {
    fn from_expr(expr: &syn::Expr) -> darling::Result<Self> {
        Ok(InitialExpr(expr.clone()))
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
