//! Writes `tests/pass/two_thousand_fields.rs`, the 2,000-variable pass test, and checks that
//! the file in the tree is what it writes: edit the generator, then run
//! `REGENERATE=1 cargo test -p ui-tests --test generated` to rewrite the file.

use std::fmt::Write;

/// The element types, in turn: every kind of variable.
const TYPES: [&str; 10] = [
    "bool",
    "u8",
    "i16",
    "u32",
    "i64",
    "f32",
    "f64",
    "u16",
    "FixedString<16>",
    "[u8; 4]",
];

/// The test's `main`: layout and values at the start, the middle and the end.
const MAIN: &str = r#"
fn main() {
    use zerocopy::IntoBytes;
    assert_eq!(Big::VARIABLES.len(), 2000);
    // The layout is that of one flat struct: every variable right after the one before,
    // nothing between or after.
    let mut end = 0;
    for v in Big::VARIABLES {
        assert_eq!(v.offset, end, "{} follows the variable before it", v.name);
        end += v.size;
    }
    assert_eq!(core::mem::size_of::<<Big as GlobalMemory>::Image>(), end);
    // Values go to the bytes VARIABLES describes, at the start, the middle and the end.
    let mut big = Big::default();
    big.v7 = 0xBEEF;
    big.v1997 = 0x1234;
    big.v1995 = 2.5;
    let image = big.to_image();
    let bytes = image.as_bytes();
    for (name, want) in [("v7", &0xBEEFu16.to_le_bytes()[..]), ("v1997", &0x1234u16.to_le_bytes()[..]), ("v1995", &2.5f32.to_le_bytes()[..])] {
        let v = &Big::VARIABLES[Big::index_of(name).unwrap()];
        assert_eq!(&bytes[v.offset..v.offset + v.size], want, "{name}");
    }
    let back = Big::from_image(&image);
    assert_eq!((back.v7, back.v1997, back.v1995), (0xBEEF, 0x1234, 2.5));
    let mut loaded = Big::default();
    loaded.load_image(&image);
    let mut stored = Big::default().to_image();
    loaded.store_image(&mut stored);
    assert_eq!(stored.as_bytes(), bytes);
}
"#;

fn two_thousand_fields() -> String {
    let mut out = String::from(
        "// A 2,000-variable struct must compile, with every kind of variable. Written by\n\
         // `tests/generated.rs`: edit that, not this.\n\
         use plc_core::{FixedString, GlobalMemory};\n\n\
         #[derive(GlobalMemory, Debug, Clone)]\n\
         pub struct Big {\n",
    );
    for i in 0..2000 {
        let ty = TYPES[i % TYPES.len()];
        let mut keys = Vec::new();
        // Every 20th a bool mapped onto the u16 three fields before it, bits 0..=15 in turn.
        if i % 20 == 0 && i > 0 {
            keys.push(format!("source = \"v{}\", bit = {}", i - 3, (i / 20) % 16));
        }
        // Every 7th number that is not 64 bits wide or a u16 source word gets an initial value.
        if i % 7 == 0 && matches!(i % 10, 1 | 2 | 3 | 5 | 6) {
            keys.push("initial = 1".to_string());
        }
        if i % 11 == 0 {
            keys.push(format!("description = \"variable {i}\""));
        }
        if !keys.is_empty() {
            writeln!(out, "    #[plc({})]", keys.join(", ")).unwrap();
        }
        writeln!(out, "    pub v{i}: {ty},").unwrap();
    }
    out.push('}');
    out.push('\n');
    out.push_str(MAIN);
    out
}

#[test]
fn the_two_thousand_field_pass_test_is_what_its_generator_writes() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/pass/two_thousand_fields.rs"
    );
    let text = two_thousand_fields();
    if std::env::var_os("REGENERATE").is_some() {
        std::fs::write(path, &text).unwrap();
    }
    let in_tree = std::fs::read_to_string(path).unwrap();
    assert!(
        in_tree == text,
        "{path} is not what tests/generated.rs writes: run it with REGENERATE=1"
    );
}
