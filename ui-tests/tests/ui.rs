//! Every compile error of `#[derive(GlobalMemory)]` (and of plc-core's compile-time checks),
//! one file per mistake under `tests/ui/<topic>/`, with the compiler's output reviewed in the
//! `.stderr` beside it; and the declarations that must compile, under `tests/pass/`.
//! Regenerate the `.stderr` files with `TRYBUILD=overwrite` and read every diff.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*/*.rs");
    t.pass("tests/pass/*.rs");
}
