//! The reserved words of IEC 61131-3 that a name must not be: the keywords, the type names and
//! the standard functions and function blocks ([`KEYWORDS`], [`TYPE_NAMES`],
//! [`STANDARD_FUNCTIONS`]), and [`reserved_word`], which also recognises the conversion
//! functions by their form.

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
