//! Every compile error of `#[derive(GlobalMemory)]` (and of plc-core's compile-time checks),
//! one file per mistake under `tests/ui/<topic>/`, with the compiler's output reviewed in the
//! `.stderr` beside it; and the declarations that must compile, under `tests/pass/`.
//! Regenerate the `.stderr` files with `TRYBUILD=overwrite` and read every diff.

#[test]
fn ui() {
    // trybuild compiles the cases in a crate of its own under `target/`: bus description
    // paths (`#[plc(bus = "tests/bus/press.toml")]`) stay relative to this crate.
    // SAFETY: set before trybuild starts any thread or process, and read only by them.
    unsafe { std::env::set_var("PLC_VARS_MANIFEST_DIR", env!("CARGO_MANIFEST_DIR")) };
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*/*.rs");
    t.pass("tests/pass/*.rs");
}
