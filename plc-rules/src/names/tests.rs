//! Tests of the naming rules and the reserved words.

use super::{NameError, check_name};

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
