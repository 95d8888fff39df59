//! Collects every error of a struct so the user sees all of them at once (serde's `Ctxt`).

use crate::loc::Loc;
use crate::symbol::{CONTAINER_KEYS, PLC, expects, field_keys, list};
use plc_rules::decl::{Issue, Wording};
use proc_macro2::{Span, TokenStream};
use std::fmt::Display;

/// How the derive writes the checker's messages: Rust names in backticks, another declaration
/// by its line.
pub struct RustWording;

impl Wording<Loc> for RustWording {
    fn name(&self, name: &str) -> String {
        format!("`{name}`")
    }

    fn place(&self, at: &Loc) -> String {
        line_of(at.span())
    }

    fn allow_unaligned(&self) -> &'static str {
        ", or allow it with `#[plc(unaligned)]` on the struct"
    }
}

#[derive(Default)]
pub struct Ctxt {
    errors: Vec<TokenStream>,
    any: bool,
    /// The declaration rules reported ([`plc_rules::decl::IssueKind::name`]), for the test
    /// that the derive and the importer agree.
    #[cfg(test)]
    pub kinds: Vec<&'static str>,
}

impl Ctxt {
    /// An error under `span`.
    pub fn error(&mut self, span: Span, message: impl Display) {
        self.syn(syn::Error::new(span, message));
    }

    /// An issue of the declaration model, under what it is about.
    pub fn issue(&mut self, issue: &Issue<Loc>) {
        #[cfg(test)]
        self.kinds.push(issue.kind.name());
        let message = issue.message(&RustWording);
        match &issue.at {
            Loc::Span(span) => self.error(*span, message),
            Loc::Tokens(tokens) => self.syn(syn::Error::new_spanned(tokens, message)),
        }
    }

    pub fn syn(&mut self, error: syn::Error) {
        self.any = true;
        self.errors.push(error.to_compile_error());
    }

    /// darling's errors, one by one, with messages in this crate's words.
    pub fn darling(&mut self, error: darling::Error) {
        self.any = true;
        for e in error.flatten() {
            let span = e.span();
            let message = darling_message(&e.to_string());
            self.errors
                .push(syn::Error::new(span, message).to_compile_error());
        }
    }

    pub fn has_errors(&self) -> bool {
        self.any
    }

    pub fn into_tokens(self) -> TokenStream {
        self.errors.into_iter().collect()
    }
}

/// ` (line N)` for an earlier declaration a message refers to, or nothing where the compiler
/// gives no line. One error that names the other place, rather than a second `error:` for it:
/// stable proc macros cannot attach a note, and a second error would count as a second mistake.
pub fn line_of(span: Span) -> String {
    match span.start().line {
        0 => String::new(),
        line => format!(" (line {line})"),
    }
}

/// Rewrites darling's generic messages ("Duplicate field `x`", "Unknown field: `x`") in terms of
/// the `#[plc(...)]` attribute; others pass through.
fn darling_message(message: &str) -> String {
    // darling appends " at <key>" for errors of one key's value: say the key first instead.
    let known = |k: &str| field_keys().any(|f| f == k) || CONTAINER_KEYS.contains(&k);
    if let Some((text, key)) = message.rsplit_once(" at ")
        && known(key)
    {
        // `alarm(...)`'s messages are this crate's own and name their key.
        return if text.contains(&format!("`{key}`")) || key == "alarm" {
            text.to_string()
        } else if let (true, Some(expected)) = (text.starts_with("Unexpected"), expects(key)) {
            format!("`{key}` takes {expected}")
        } else {
            format!("`{key}`: {}", lowercase_first(text))
        };
    }
    let quoted = |s: &str| s.split('`').nth(1).unwrap_or_default().to_string();
    if message.starts_with("Duplicate field `") {
        let key = quoted(message);
        return format!("`{key}` is given twice in `#[{PLC}(...)]`: keep one");
    }
    if let Some(rest) = message.strip_prefix("Unknown field: ") {
        let key = quoted(rest);
        let hint = if let Some((_, alt)) = rest.split_once(". Did you mean ") {
            format!("did you mean {}", alt.trim())
        } else if rest.contains("Available values:") {
            format!(
                "the keys on the struct are {}",
                list(CONTAINER_KEYS.iter().copied())
            )
        } else {
            format!("the keys on a field are {}", list(field_keys()))
        };
        return format!("unknown key `{key}` in `#[{PLC}(...)]`: {hint}");
    }
    message.to_string()
}

fn lowercase_first(s: &str) -> String {
    let mut chars = s.chars();
    chars.next().map_or_else(String::new, |c| {
        c.to_lowercase().chain(chars).collect::<String>()
    })
}

#[cfg(test)]
mod tests {
    use super::darling_message;

    #[test]
    fn line_of_names_the_line_of_a_span() {
        let tokens: proc_macro2::TokenStream = "first\n\n  second".parse().unwrap();
        let spans: Vec<_> = tokens.into_iter().map(|t| t.span()).collect();
        assert_eq!(super::line_of(spans[0]), " (line 1)");
        assert_eq!(super::line_of(spans[1]), " (line 3)");
    }

    #[test]
    fn darling_messages_name_the_attribute() {
        assert_eq!(
            darling_message("Duplicate field `bit`"),
            "`bit` is given twice in `#[plc(...)]`: keep one"
        );
        assert_eq!(
            darling_message("Unknown field: `linkk`. Did you mean `link`?"),
            "unknown key `linkk` in `#[plc(...)]`: did you mean `link`?"
        );
        assert!(darling_message("Unknown field: `colour`").contains("`iec_type`"));
        assert_eq!(
            darling_message("Unexpected type `int`"),
            "Unexpected type `int`"
        );
    }
}
