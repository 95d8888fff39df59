//! The naming rules a name must follow, [`check_name`] and its [`NameError`], and comparing
//! names: [`same_name`] and, for hints, `nearest`.

use super::reserved::reserved_word;
use core::fmt;

/// Why a name breaks the variable-editor naming rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NameError {
    /// The name is empty.
    Empty,
    /// The name starts with a digit.
    StartsWithDigit,
    /// The name holds a character other than an ASCII letter, digit or underscore.
    InvalidChar(char),
    /// The name holds two consecutive underscores.
    DoubleUnderscore,
    /// The name is a keyword, a type name or a standard function or function block (the
    /// reserved word, in upper case).
    Reserved(&'static str),
}

impl fmt::Display for NameError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NameError::Empty => f.write_str("a name must not be empty"),
            NameError::StartsWithDigit => {
                f.write_str("a name must begin with a letter or an underscore, not a digit")
            }
            NameError::InvalidChar(c) if c.is_control() || c.is_whitespace() => write!(
                f,
                "`{}` is not allowed in a name: use ASCII letters, digits and underscores",
                c.escape_default()
            ),
            NameError::InvalidChar(c) => write!(
                f,
                "`{c}` is not allowed in a name: use ASCII letters, digits and underscores"
            ),
            NameError::DoubleUnderscore => {
                f.write_str("a name must not contain two consecutive underscores")
            }
            NameError::Reserved(word) => write!(
                f,
                "`{word}` is reserved in IEC 61131-3 (a keyword, type, or standard function or \
                 function block): choose another name"
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for NameError {}

/// Checks one name against the variable-editor naming rules.
pub fn check_name(name: &str) -> Result<(), NameError> {
    let first = name.chars().next().ok_or(NameError::Empty)?;
    if first.is_ascii_digit() {
        return Err(NameError::StartsWithDigit);
    }
    if let Some(c) = name
        .chars()
        .find(|c| !(c.is_ascii_alphanumeric() || *c == '_'))
    {
        return Err(NameError::InvalidChar(c));
    }
    if name.contains("__") {
        return Err(NameError::DoubleUnderscore);
    }
    match reserved_word(name) {
        Some(word) => Err(NameError::Reserved(word)),
        None => Ok(()),
    }
}

/// Whether two names are the same name (the variable-editor rules: naming is case insensitive).
pub fn same_name(a: &str, b: &str) -> bool {
    a.eq_ignore_ascii_case(b)
}

/// The name of `names` nearest `wrong` (case-insensitively), if one is near: a typo or two,
/// at most a third of its characters changed. For "did you mean" hints.
#[cfg(feature = "std")]
pub fn nearest<'a>(wrong: &str, names: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let wrong_lower = std::string::String::from(wrong).to_ascii_lowercase();
    let limit = wrong.chars().count().div_ceil(3);
    names
        .into_iter()
        .map(|n| (edit_distance(&wrong_lower, &n.to_ascii_lowercase()), n))
        .filter(|&(d, _)| d <= limit)
        .min_by_key(|&(d, _)| d)
        .map(|(_, n)| n)
}

/// Levenshtein distance of two short names, by characters.
#[cfg(feature = "std")]
fn edit_distance(a: &str, b: &str) -> usize {
    use std::vec::Vec;
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (above + 1)
                .min(row[j] + 1)
                .min(diagonal + usize::from(ca != *cb));
            diagonal = above;
        }
    }
    row[b.len()]
}
