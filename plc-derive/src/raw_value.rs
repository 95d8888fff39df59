//! The tokens a key of `#[plc(...)]` was written with, for errors under the whole value (the
//! attribute readers and the alarm reader both need them, below either).

use crate::symbol::PLC;
use proc_macro2::{TokenStream, TokenTree};

/// The tokens written after `key =` in the `#[plc(...)]` attributes, exactly as the user wrote
/// them. syn folds `-1` into one literal spanned by the `-` alone (stable Rust cannot join
/// spans), so an error under the whole value needs the raw tokens. `None` if the key is absent.
pub fn raw_value(attrs: &[syn::Attribute], key: &str) -> Option<TokenStream> {
    attrs
        .iter()
        .filter(|a| a.path().is_ident(PLC))
        .filter_map(|a| match &a.meta {
            syn::Meta::List(list) => Some(list.tokens.clone()),
            _ => None,
        })
        .find_map(|tokens| value_in(tokens, key))
}

/// The tokens after `key =` among `tokens` (an attribute's, or a nested list's such as
/// `alarm(...)`'s), up to the next comma; `None` if the key is absent.
pub fn value_in(tokens: TokenStream, key: &str) -> Option<TokenStream> {
    let tokens: Vec<TokenTree> = tokens.into_iter().collect();
    let start = tokens.windows(2).position(|w| {
        matches!(&w[0], TokenTree::Ident(i) if i == key)
            && matches!(&w[1], TokenTree::Punct(p) if p.as_char() == '=')
    })?;
    let value = tokens[start + 2..]
        .iter()
        .take_while(|t| !matches!(t, TokenTree::Punct(p) if p.as_char() == ','))
        .cloned()
        .collect::<TokenStream>();
    (!value.is_empty()).then_some(value)
}

#[cfg(test)]
mod tests {
    use super::raw_value;

    #[test]
    fn raw_value_keeps_each_token_of_a_negative_number() {
        let field: syn::DeriveInput = syn::parse_str(
            "#[doc = \"x\"] #[plc(bit = 2, initial = -1, link = \"a.b\")] struct S;",
        )
        .unwrap();
        let initial = raw_value(&field.attrs, "initial").unwrap();
        assert_eq!(
            initial.into_iter().count(),
            2,
            "`-` and `1`, each with its span"
        );
        assert_eq!(raw_value(&field.attrs, "bit").unwrap().to_string(), "2");
        assert!(raw_value(&field.attrs, "source").is_none());
    }
}
