//! The importer's output for a list whose text rustc would refuse in source
//! (`plc-io/tests/golden/hostile.rs`, pinned by plc-io's import test), compiled as a user's
//! crate compiles it: rustc denies bidirectional controls in comments and literals by default,
//! so this file compiling is the test that the importer escaped them. The descriptions keep
//! their exact text.
#![deny(missing_docs)]

include!("../../plc-io/tests/golden/hostile.rs");

#[test]
fn the_descriptions_and_initials_keep_their_exact_text() {
    let v = Hostile::VARIABLES;
    assert_eq!(
        v[0].description,
        "Start \u{202e}evil\u{202c} here\u{2066}x\u{2069}"
    );
    assert_eq!(v[1].description, "rings\u{7} twice\tand more");
    assert_eq!(v[2].name, "loop");
    assert_eq!(v[2].description, "line one line two line three");
    assert_eq!(Hostile::default().label.as_str(), "ok\u{202e}");
}
