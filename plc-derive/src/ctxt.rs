//! Collects every error of a struct so the user sees all of them at once (serde's `Ctxt`).

use proc_macro2::{Span, TokenStream};
use std::fmt::Display;

#[derive(Default)]
pub struct Ctxt {
    errors: Vec<TokenStream>,
    any: bool,
}

impl Ctxt {
    /// An error under `span`.
    pub fn error(&mut self, span: Span, message: impl Display) {
        self.syn(syn::Error::new(span, message));
    }

    /// An error under `span`, with a note pointing at an earlier declaration.
    pub fn error_with_previous(
        &mut self,
        span: Span,
        message: impl Display,
        previous: Span,
        note: impl Display,
    ) {
        let mut e = syn::Error::new(span, message);
        e.combine(syn::Error::new(previous, note));
        self.syn(e);
    }

    pub fn syn(&mut self, error: syn::Error) {
        self.any = true;
        self.errors.push(error.to_compile_error());
    }

    pub fn darling(&mut self, error: darling::Error) {
        self.any = true;
        self.errors.push(error.write_errors());
    }

    pub fn has_errors(&self) -> bool {
        self.any
    }

    pub fn into_tokens(self) -> TokenStream {
        self.errors.into_iter().collect()
    }
}
