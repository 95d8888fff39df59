//! The variable-editor naming rules for variables (and link identifiers).
//!
//! A name begins with a letter or an underscore, followed by letters, digits or underscores
//! (ASCII), has no two consecutive underscores, is not a reserved keyword, an IEC type name, or
//! the name of a standard function or function block, and is compared case-insensitively.
//!
//! ```
//! use plc_rules::names::{check_name, NameError};
//! assert_eq!(check_name("ls_centering_neg"), Ok(()));
//! assert_eq!(check_name("motor__speed"), Err(NameError::DoubleUnderscore));
//! assert_eq!(check_name("ton"), Err(NameError::Reserved("TON")));
//! assert!(plc_rules::names::same_name("Speed", "SPEED"));
//! ```

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

/// Keywords of the IEC 61131-3 languages (ST, IL, SFC, declarations).
pub const KEYWORDS: &[&str] = &[
    "ACTION",
    "END_ACTION",
    "ARRAY",
    "OF",
    "AT",
    "CASE",
    "ELSE",
    "END_CASE",
    "CONFIGURATION",
    "END_CONFIGURATION",
    "CONSTANT",
    "EN",
    "ENO",
    "EXIT",
    "FALSE",
    "F_EDGE",
    "FOR",
    "TO",
    "BY",
    "DO",
    "END_FOR",
    "FUNCTION",
    "END_FUNCTION",
    "FUNCTION_BLOCK",
    "END_FUNCTION_BLOCK",
    "IF",
    "THEN",
    "ELSIF",
    "END_IF",
    "INITIAL_STEP",
    "END_STEP",
    "NOT",
    "MOD",
    "AND",
    "OR",
    "XOR",
    "PROGRAM",
    "WITH",
    "END_PROGRAM",
    "R_EDGE",
    "READ_ONLY",
    "READ_WRITE",
    "REPEAT",
    "UNTIL",
    "END_REPEAT",
    "RESOURCE",
    "ON",
    "END_RESOURCE",
    "RETAIN",
    "NON_RETAIN",
    "RETURN",
    "STEP",
    "STRUCT",
    "END_STRUCT",
    "TASK",
    "TRANSITION",
    "FROM",
    "END_TRANSITION",
    "TRUE",
    "TYPE",
    "END_TYPE",
    "VAR",
    "END_VAR",
    "VAR_INPUT",
    "VAR_OUTPUT",
    "VAR_IN_OUT",
    "VAR_TEMP",
    "VAR_EXTERNAL",
    "VAR_ACCESS",
    "VAR_CONFIG",
    "VAR_GLOBAL",
    "WHILE",
    "END_WHILE",
    "JMP",
    "CAL",
    "RET",
    "LD",
    "LDN",
    "ST",
    "STN",
    "S",
    "R",
    "ANDN",
    "ORN",
    "XORN",
    "CALC",
    "CALCN",
    "RETC",
    "RETCN",
    "JMPC",
    "JMPCN",
    "PRIORITY",
    "SINGLE",
    "INTERVAL",
    "NIL",
    "REF",
    "REF_TO",
    "THIS",
    "SUPER",
    "METHOD",
    "END_METHOD",
    "INTERFACE",
    "END_INTERFACE",
    "EXTENDS",
    "IMPLEMENTS",
];

/// Elementary and generic type names.
pub const TYPE_NAMES: &[&str] = &[
    "BOOL",
    "SINT",
    "INT",
    "DINT",
    "LINT",
    "USINT",
    "UINT",
    "UDINT",
    "ULINT",
    "REAL",
    "LREAL",
    "TIME",
    "LTIME",
    "DATE",
    "LDATE",
    "TIME_OF_DAY",
    "TOD",
    "LTOD",
    "DATE_AND_TIME",
    "DT",
    "LDT",
    "STRING",
    "WSTRING",
    "CHAR",
    "WCHAR",
    "BYTE",
    "WORD",
    "DWORD",
    "LWORD",
    "ANY",
    "ANY_DERIVED",
    "ANY_ELEMENTARY",
    "ANY_MAGNITUDE",
    "ANY_NUM",
    "ANY_REAL",
    "ANY_INT",
    "ANY_BIT",
    "ANY_STRING",
    "ANY_DATE",
    "ANY_SIGNED",
    "ANY_UNSIGNED",
    "ANY_DURATION",
    "ANY_CHAR",
    "ANY_CHARS",
];

/// Standard functions and function blocks (IEC 61131-3 ed. 3 tables 22-36 and 43-46), which
/// the variable-editor rules reserve. The conversion functions (`<TYPE>_TO_<TYPE>`, `TO_<TYPE>`,
/// `<TYPE>_TRUNC_<TYPE>`, `TRUNC_<TYPE>`, and the BCD forms) are recognised by pattern instead,
/// as [`reserved_word`] does.
pub const STANDARD_FUNCTIONS: &[&str] = &[
    "ABS",
    "SQRT",
    "LN",
    "LOG",
    "EXP",
    "SIN",
    "COS",
    "TAN",
    "ASIN",
    "ACOS",
    "ATAN",
    "ATAN2",
    "ADD",
    "MUL",
    "SUB",
    "DIV",
    "EXPT",
    "MOVE",
    "SHL",
    "SHR",
    "ROR",
    "ROL",
    "SEL",
    "MAX",
    "MIN",
    "LIMIT",
    "MUX",
    "GT",
    "GE",
    "EQ",
    "LE",
    "LT",
    "NE",
    "LEN",
    "LEFT",
    "RIGHT",
    "MID",
    "CONCAT",
    "INSERT",
    "DELETE",
    "REPLACE",
    "FIND",
    "TRUNC",
    "SR",
    "RS",
    "SEMA",
    "R_TRIG",
    "F_TRIG",
    "CTU",
    "CTD",
    "CTUD",
    "CTU_INT",
    "CTD_INT",
    "CTUD_INT",
    "CTU_DINT",
    "CTD_DINT",
    "CTUD_DINT",
    "CTU_LINT",
    "CTD_LINT",
    "CTUD_LINT",
    "CTU_UDINT",
    "CTD_UDINT",
    "CTUD_UDINT",
    "CTU_ULINT",
    "CTD_ULINT",
    "CTUD_ULINT",
    "TP",
    "TON",
    "TOF",
    "LTP",
    "LTON",
    "LTOF",
    "RTC",
    // Time and date functions (tables 35 and 36), with their LTIME/LDATE/LTOD/LDT forms.
    "ADD_TIME",
    "ADD_TOD_TIME",
    "ADD_DT_TIME",
    "SUB_TIME",
    "SUB_DATE_DATE",
    "SUB_TOD_TIME",
    "SUB_TOD_TOD",
    "SUB_DT_TIME",
    "SUB_DT_DT",
    "MUL_TIME",
    "DIV_TIME",
    "CONCAT_DATE_TOD",
    "CONCAT_DATE",
    "CONCAT_TOD",
    "CONCAT_DT",
    "SPLIT_DATE",
    "SPLIT_TOD",
    "SPLIT_DT",
    "DAY_OF_WEEK",
    "ADD_LTIME",
    "ADD_LTOD_LTIME",
    "ADD_LDT_LTIME",
    "SUB_LTIME",
    "SUB_LDATE_LDATE",
    "SUB_LTOD_LTIME",
    "SUB_LTOD_LTOD",
    "SUB_LDT_LTIME",
    "SUB_LDT_LDT",
    "MUL_LTIME",
    "DIV_LTIME",
    "CONCAT_LDATE_LTOD",
    "CONCAT_LDATE",
    "CONCAT_LTOD",
    "CONCAT_LDT",
    "SPLIT_LDATE",
    "SPLIT_LTOD",
    "SPLIT_LDT",
    // Endianness conversion and validation (ed. 3).
    "TO_BIG_ENDIAN",
    "TO_LITTLE_ENDIAN",
    "BIG_ENDIAN_TO",
    "LITTLE_ENDIAN_TO",
    "IS_VALID",
    "IS_VALID_BCD",
];

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

/// The reserved word `name` equals (case-insensitively), if any.
pub fn reserved_word(name: &str) -> Option<&'static str> {
    let lists = [KEYWORDS, TYPE_NAMES, STANDARD_FUNCTIONS];
    if let Some(word) = lists
        .iter()
        .flat_map(|l| l.iter())
        .find(|w| w.eq_ignore_ascii_case(name))
    {
        return Some(word);
    }
    conversion_function(name)
}

/// Recognises the standard conversion functions by their form (IEC 61131-3 ed. 3 table 22):
/// typed `<TYPE>_TO_<TYPE>` and `<TYPE>_TRUNC_<TYPE>`, overloaded `TO_<TYPE>` and
/// `TRUNC_<TYPE>`, and the BCD forms `<TYPE>_BCD_TO_<TYPE>`, `<TYPE>_TO_BCD_<TYPE>`,
/// `BCD_TO_<TYPE>` and `TO_BCD_<TYPE>`. Returns the form, as the reserved word to report.
fn conversion_function(name: &str) -> Option<&'static str> {
    let is_type = |t: &str| TYPE_NAMES.iter().any(|w| w.eq_ignore_ascii_case(t));
    // A source may be BCD-coded (`WORD_BCD`), or just `BCD`; a target likewise (`BCD_WORD`).
    let source =
        |t: &str| t.eq_ignore_ascii_case("BCD") || is_type(strip_suffix_ci(t, "_BCD").unwrap_or(t));
    let target =
        |t: &str| t.eq_ignore_ascii_case("BCD") || is_type(strip_prefix_ci(t, "BCD_").unwrap_or(t));
    if let Some(t) = strip_prefix_ci(name, "TO_")
        && target(t)
    {
        return Some("TO_<TYPE>");
    }
    if let Some(t) = strip_prefix_ci(name, "TRUNC_")
        && is_type(t)
    {
        return Some("TRUNC_<TYPE>");
    }
    let forms: [(&[u8], &'static str); 2] = [
        (b"_TO_", "<TYPE>_TO_<TYPE>"),
        (b"_TRUNC_", "<TYPE>_TRUNC_<TYPE>"),
    ];
    let bytes = name.as_bytes();
    forms.into_iter().find_map(|(infix, form)| {
        // Every split point, as a type name may hold an underscore (`TIME_OF_DAY`). The infix
        // is ASCII, so both ends of a match are character boundaries.
        (0..bytes.len().saturating_sub(infix.len() - 1))
            .filter(|&i| bytes[i..i + infix.len()].eq_ignore_ascii_case(infix))
            .any(|i| source(&name[..i]) && target(&name[i + infix.len()..]))
            .then_some(form)
    })
}

/// `s` without the ASCII prefix `p`, compared case-insensitively.
fn strip_prefix_ci<'a>(s: &'a str, p: &str) -> Option<&'a str> {
    let n = p.len();
    (s.len() >= n && s.as_bytes()[..n].eq_ignore_ascii_case(p.as_bytes())).then(|| &s[n..])
}

/// `s` without the ASCII suffix `p`, compared case-insensitively.
fn strip_suffix_ci<'a>(s: &'a str, p: &str) -> Option<&'a str> {
    let n = s.len().checked_sub(p.len())?;
    s.as_bytes()[n..]
        .eq_ignore_ascii_case(p.as_bytes())
        .then(|| &s[..n])
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_format_and_editor_style_names_are_accepted() {
        for ok in [
            "ls_centering_neg",
            "_hidden",
            "x1",
            "Impact67_0_digital_inputs",
            "a_b_c_",
        ] {
            assert_eq!(check_name(ok), Ok(()), "{ok}");
        }
    }

    #[test]
    fn each_rule_is_reported() {
        assert_eq!(check_name(""), Err(NameError::Empty));
        assert_eq!(check_name("1abc"), Err(NameError::StartsWithDigit));
        assert_eq!(check_name("a-b"), Err(NameError::InvalidChar('-')));
        assert_eq!(check_name("größe"), Err(NameError::InvalidChar('ö')));
        assert_eq!(check_name("a__b"), Err(NameError::DoubleUnderscore));
        assert_eq!(check_name("End_Var"), Err(NameError::Reserved("END_VAR")));
        assert_eq!(check_name("dint"), Err(NameError::Reserved("DINT")));
        assert_eq!(check_name("abs"), Err(NameError::Reserved("ABS")));
        assert_eq!(check_name("r_trig"), Err(NameError::Reserved("R_TRIG")));
        assert_eq!(check_name("Ton"), Err(NameError::Reserved("TON")));
        assert!(matches!(
            check_name("INT_TO_REAL"),
            Err(NameError::Reserved(_))
        ));
        assert!(matches!(
            check_name("word_bcd_to_int"),
            Err(NameError::Reserved(_))
        ));
        // Names that merely contain a reserved word stay legal.
        assert_eq!(check_name("ton_preset"), Ok(()));
        assert_eq!(check_name("speed_to_motor"), Ok(()));
    }

    #[test]
    fn every_form_of_conversion_function_is_reserved() {
        let reserved = |name: &str| match check_name(name) {
            Err(NameError::Reserved(form)) => form,
            other => panic!("{name}: {other:?}"),
        };
        assert_eq!(reserved("DINT_TO_INT"), "<TYPE>_TO_<TYPE>");
        assert_eq!(reserved("time_of_day_to_dint"), "<TYPE>_TO_<TYPE>");
        assert_eq!(reserved("TO_INT"), "TO_<TYPE>");
        assert_eq!(reserved("to_lreal"), "TO_<TYPE>");
        assert_eq!(reserved("TO_BCD_WORD"), "TO_<TYPE>");
        assert_eq!(reserved("REAL_TRUNC_INT"), "<TYPE>_TRUNC_<TYPE>");
        assert_eq!(reserved("TRUNC_DINT"), "TRUNC_<TYPE>");
        assert_eq!(reserved("WORD_BCD_TO_UINT"), "<TYPE>_TO_<TYPE>");
        assert_eq!(reserved("USINT_TO_BCD_BYTE"), "<TYPE>_TO_<TYPE>");
        assert_eq!(reserved("BCD_TO_INT"), "<TYPE>_TO_<TYPE>");
        assert_eq!(reserved("TRUNC"), "TRUNC");
        // What only looks like one stays legal.
        for ok in [
            "to_motor",
            "trunc_length",
            "speed_trunc_int",
            "to_",
            "x_to_",
        ] {
            assert_eq!(check_name(ok), Ok(()), "{ok}");
        }
    }

    #[test]
    fn standard_functions_of_edition_3_are_reserved() {
        for word in [
            "SUB_DT_DT",
            "concat_ltod",
            "TO_BIG_ENDIAN",
            "little_endian_to",
            "IS_VALID",
            "IS_VALID_BCD",
            "ADD_TOD_TIME",
            "split_ldt",
        ] {
            assert!(
                matches!(check_name(word), Err(NameError::Reserved(_))),
                "{word}"
            );
        }
    }
}
