//! Where a declaration was written, for the errors that point at it.

use plc_rules::decl::Located;
use proc_macro2::{Span, TokenStream};

/// A value of a declaration with where it was written.
pub type At<T> = Located<T, Loc>;

/// Where a declaration was written: a span, or the tokens of a value (syn folds `-1` into one
/// literal spanned by the `-` alone, and stable Rust cannot join spans, so an error under the
/// whole value needs its tokens).
#[derive(Clone, Debug)]
pub enum Loc {
    Span(Span),
    Tokens(TokenStream),
}

impl Loc {
    /// The span an error starts at.
    pub fn span(&self) -> Span {
        match self {
            Loc::Span(s) => *s,
            Loc::Tokens(t) => t
                .clone()
                .into_iter()
                .next()
                .map_or_else(Span::call_site, |t| t.span()),
        }
    }
}
