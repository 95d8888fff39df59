//! The `#[plc(...)]` attribute as written, one darling receiver per site. Validation beyond
//! syntax lives in `ast` (per field) and `check` (across fields).

use darling::util::{Flag, SpannedValue};
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
    pub unaligned: Flag,
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
    pub nonvolatile: Flag,
    pub retain: Flag,
    pub description: Option<SpannedValue<String>>,
    pub read_only: Flag,
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
