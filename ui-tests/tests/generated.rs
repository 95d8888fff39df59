//! Writes `tests/pass/two_thousand_fields.rs`, the 2,000-variable pass test, and
//! `tests/runs/generated.rs`, random declarations against straight-line reference code (the
//! test `runs_equivalence` includes it; outside the test targets, so rustfmt leaves it as
//! written), and
//! checks that the files in the tree are what it writes: edit the generator, then run
//! `REGENERATE=1 cargo test -p ui-tests --test generated` to rewrite them.

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
    // Access by index on both sides of the chunks `try_get` and `set` are split into (1,024
    // variables each), and a bool in the second chunk mapped onto a word in the first.
    use plc_core::{SetError, Value};
    let mut gm = Big::default();
    let at = |name: &str| Big::index_of(name).unwrap();
    for (name, value) in [("v7", 7), ("v1017", 1017), ("v1027", 1027), ("v1997", 1997)] {
        gm.set(at(name), 0, Value::UInt(value)).unwrap();
        assert_eq!(gm.try_get(at(name), 0), Some(Value::UInt(value)), "{name}");
    }
    assert_eq!((gm.v7, gm.v1017, gm.v1027, gm.v1997), (7, 1017, 1027, 1997));
    gm.set(at("v1017"), 0, Value::UInt(0)).unwrap();
    gm.set(at("v1030"), 0, Value::Bool(true)).unwrap();
    assert_eq!(gm.v1017, 1 << 9, "the bool set its bit of the word in the chunk before");
    gm.set(at("v1017"), 0, Value::UInt(1 << 3)).unwrap();
    assert!(!gm.v1030 && gm.v1020, "the word set the bools mapped onto it");
    assert_eq!(gm.try_get(2000, 0), None);
    assert!(matches!(gm.set(2000, 0, Value::Bool(true)), Err(SetError::UnknownIndex { index: 2000 })));
    // The layout hash, computed in parts of 1,024 variables, is that of the whole list.
    assert_eq!(Big::LAYOUT_HASH, plc_core::__private::layout_hash(Big::VARIABLES));
    // A fresh struct is all zero where no initial value says otherwise.
    let fresh = Big::default();
    assert_eq!((fresh.v7, fresh.v1997, fresh.v1996, fresh.v0), (0, 0, 0.0, false));
    assert_eq!(fresh.v1995, 1.0, "its initial value");
    assert_eq!(fresh.v8.len(), 0);
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
        // A bool of `set`'s second chunk mapped onto a word of its first.
        if i == 1030 {
            keys.push("source = \"v1017\", bit = 9".to_string());
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

/// Writes `text` to `path` under `REGENERATE`, and checks the file in the tree is `text`.
fn in_tree_is(path: &str, text: &str) {
    if std::env::var_os("REGENERATE").is_some() {
        std::fs::write(path, text).unwrap();
    }
    let in_tree = std::fs::read_to_string(path).unwrap();
    assert!(
        in_tree == text,
        "{path} is not what tests/generated.rs writes: run it with REGENERATE=1"
    );
}

#[test]
fn the_two_thousand_field_pass_test_is_what_its_generator_writes() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/pass/two_thousand_fields.rs"
    );
    in_tree_is(path, &two_thousand_fields());
}

#[test]
fn the_runs_equivalence_test_is_what_its_generator_writes() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/runs/generated.rs");
    in_tree_is(path, &runs::equivalence());
}

/// Random declarations whose conversions the derive does in loops over runs of fields and of
/// bit-mapped bools (`plc-derive/src/expand/runs.rs`), each with reference code that converts
/// field by field as the straight-line code does.
mod runs {
    use std::fmt::Write;

    /// Field types: every kind, aliases and structures included.
    const TYPES: [&str; 18] = [
        "bool",
        "u8",
        "i8",
        "u16",
        "i16",
        "u32",
        "i32",
        "u64",
        "i64",
        "f32",
        "f64",
        "FixedString<5>",
        "[u16; 3]",
        "[[i8; 2]; 2]",
        "Word",
        "Flag",
        "Pair",
        "[Pair; 2]",
    ];

    /// Integer types a bool can be mapped onto.
    const WORDS: [&str; 5] = ["u8", "u16", "i32", "u64", "Word"];

    /// A fixed-seed xorshift: the same declarations every time.
    struct Rng(u64);

    impl Rng {
        fn below(&mut self, n: usize) -> usize {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 % n as u64) as usize
        }
    }

    /// One field: name, type, and the source field and bit of a mapped bool.
    type Field = (String, String, Option<(String, u32)>);

    /// The fields of one random declaration, in stretches: repeated blocks of types, single
    /// fields, words with bools mapped in order (bit runs) and out of order.
    fn fields(rng: &mut Rng) -> Vec<Field> {
        let mut out: Vec<Field> = Vec::new();
        let name = |out: &Vec<Field>| format!("f{}", out.len());
        for _ in 0..8 {
            match rng.below(4) {
                0 => {
                    let period = 1 + rng.below(5);
                    let block: Vec<&str> =
                        (0..period).map(|_| TYPES[rng.below(TYPES.len())]).collect();
                    for _ in 0..(4 + rng.below(40)) {
                        for ty in &block {
                            out.push((name(&out), ty.to_string(), None));
                        }
                    }
                }
                1 => {
                    for _ in 0..(1 + rng.below(6)) {
                        out.push((name(&out), TYPES[rng.below(TYPES.len())].into(), None));
                    }
                }
                2 => {
                    let ty = WORDS[rng.below(WORDS.len())];
                    let width = match ty {
                        "u8" => 8,
                        "u16" | "Word" => 16,
                        "i32" => 32,
                        _ => 64,
                    };
                    let words: Vec<String> = (0..(2 + rng.below(12)))
                        .map(|_| {
                            let w = name(&out);
                            out.push((w.clone(), ty.into(), None));
                            w
                        })
                        .collect();
                    let first = rng.below(width / 2) as u32;
                    let bits = 1 + rng.below(width - first as usize);
                    let bool_ty = if rng.below(3) == 0 { "Flag" } else { "bool" };
                    for w in &words {
                        for b in 0..bits as u32 {
                            out.push((name(&out), bool_ty.into(), Some((w.clone(), first + b))));
                        }
                    }
                }
                _ => {
                    let words: Vec<String> = (0..3)
                        .map(|_| {
                            let w = name(&out);
                            out.push((w.clone(), "u16".into(), None));
                            w
                        })
                        .collect();
                    let mut taken = Vec::new();
                    for _ in 0..(4 + rng.below(20)) {
                        let at = (words[rng.below(3)].clone(), rng.below(16) as u32);
                        if !taken.contains(&at) {
                            taken.push(at.clone());
                            out.push((name(&out), "bool".into(), Some(at)));
                        }
                    }
                }
            }
        }
        out
    }

    /// The declaration `name` and its reference conversions.
    fn declaration(w: &mut String, name: &str, fields: &[Field]) {
        writeln!(
            w,
            "#[derive(GlobalMemory, Debug, Clone)]\npub struct {name} {{"
        )
        .unwrap();
        for (f, ty, map) in fields {
            if let Some((s, b)) = map {
                writeln!(w, "    #[plc(source = \"{s}\", bit = {b})]").unwrap();
            }
            writeln!(w, "    pub {f}: {ty},").unwrap();
        }
        writeln!(w, "}}\n\nimpl Reference for {name} {{").unwrap();
        writeln!(
            w,
            "    fn reference_store(&self) -> Vec<u8> {{\n        let mut b = Vec::new();"
        )
        .unwrap();
        for (f, ty, _) in fields {
            writeln!(
                w,
                "        b.extend_from_slice(<{ty} as PlcType>::to_repr(&self.{f}).as_bytes());"
            )
            .unwrap();
        }
        writeln!(w, "        b\n    }}\n\n    fn reference_load(&mut self, b: &[u8]) {{\n        let mut at = 0;").unwrap();
        for (f, ty, _) in fields {
            writeln!(
                w,
                "        self.{f} = <{ty} as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);\n        \
                 at += size_of::<<{ty} as PlcType>::Repr>();"
            )
            .unwrap();
        }
        writeln!(
            w,
            "        assert_eq!(at, b.len());\n    }}\n\n    fn reference_unpack(&mut self) {{"
        )
        .unwrap();
        for (f, _, map) in fields {
            if let Some((s, b)) = map {
                writeln!(w, "        self.{f} = (self.{s} >> {b}) & 1 != 0;").unwrap();
            }
        }
        writeln!(w, "        self.reference_unpack_nested();\n    }}\n\n    fn reference_pack(&mut self) {{\n        self.reference_pack_nested();").unwrap();
        for (f, _, map) in fields {
            if let Some((s, b)) = map {
                let word = &fields.iter().find(|(n, _, _)| n == s).unwrap().1;
                writeln!(
                    w,
                    "        self.{s} = (self.{s} & !(1 << {b})) | ((self.{f} as {word}) << {b});"
                )
                .unwrap();
            }
        }
        writeln!(w, "    }}\n\n    fn reference_unpack_nested(&mut self) {{").unwrap();
        let nested: Vec<_> = fields
            .iter()
            .filter(|(_, ty, _)| ty.contains("Pair"))
            .collect();
        for (f, ty, _) in &nested {
            if ty == "Pair" {
                writeln!(w, "        self.{f}.reference_unpack();").unwrap();
            } else {
                writeln!(
                    w,
                    "        self.{f}.iter_mut().for_each(Pair::reference_unpack);"
                )
                .unwrap();
            }
        }
        writeln!(w, "    }}\n\n    fn reference_pack_nested(&mut self) {{").unwrap();
        for (f, ty, _) in &nested {
            if ty == "Pair" {
                writeln!(w, "        self.{f}.reference_pack();").unwrap();
            } else {
                writeln!(
                    w,
                    "        self.{f}.iter_mut().for_each(Pair::reference_pack);"
                )
                .unwrap();
            }
        }
        writeln!(w, "    }}\n}}\n").unwrap();
    }

    /// What every declaration is tested for; `tests/runs_equivalence.rs` includes the file.
    const HEADER: &str = r#"// Written by `tests/generated.rs`: edit that, not this.

use core::mem::size_of;
use plc_core::{FixedString, GlobalMemory, PlcStruct, PlcType};
use proptest::prelude::*;
use zerocopy::{FromBytes, IntoBytes};

type Word = u16;
type Flag = bool;

#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
pub struct Pair {
    pub a: u16,
    #[plc(source = "a", bit = 3)]
    pub b: bool,
    pub c: f32,
}

impl Pair {
    fn reference_unpack(&mut self) {
        self.b = (self.a >> 3) & 1 != 0;
    }

    fn reference_pack(&mut self) {
        self.a = (self.a & !(1 << 3)) | ((self.b as u16) << 3);
    }
}

/// Field-by-field conversions, as the derive's straight-line code does them.
trait Reference: GlobalMemory {
    fn reference_store(&self) -> Vec<u8>;
    fn reference_load(&mut self, bytes: &[u8]);
    fn reference_unpack(&mut self);
    fn reference_pack(&mut self);
    fn reference_unpack_nested(&mut self);
    fn reference_pack_nested(&mut self);
}

/// Loads, stores, unpacks and packs `bytes` both ways and compares the results as bytes (NaN
/// is not equal to itself).
fn agree<T: Reference + Clone>(bytes: &[u8]) {
    let image = T::Image::read_from_bytes(bytes).unwrap();
    let mut ours = T::from_image(&image);
    let mut theirs = T::from_image(&image);
    ours.load_image(&image);
    theirs.reference_load(bytes);
    assert_eq!(ours.reference_store(), theirs.reference_store(), "load_image");
    assert_eq!(ours.to_image().as_bytes(), theirs.reference_store().as_slice(), "store_image");
    ours.unpack_bits();
    theirs.reference_unpack();
    assert_eq!(ours.reference_store(), theirs.reference_store(), "unpack_bits");
    // Other values in the bools before packing, so every bit changes somewhere.
    let mut flipped = ours.to_image();
    flipped.as_mut_bytes().iter_mut().for_each(|b| *b = !*b);
    let bools = T::from_image(&flipped);
    let mut ours = bools.clone();
    let mut theirs = bools;
    ours.pack_bits();
    theirs.reference_pack();
    assert_eq!(ours.reference_store(), theirs.reference_store(), "pack_bits");
}
"#;

    /// The test file: the declarations, then a property per declaration.
    pub fn equivalence() -> String {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        let mut w = String::from(HEADER);
        let names: Vec<String> = (0..3).map(|i| format!("Random{i}")).collect();
        for name in &names {
            w.push('\n');
            declaration(&mut w, name, &fields(&mut rng));
        }
        w.push_str("proptest! {\n    #![proptest_config(ProptestConfig::with_cases(64))]\n");
        for name in &names {
            let size = format!("size_of::<<{name} as GlobalMemory>::Image>()");
            write!(
                w,
                "\n    #[test]\n    fn loops_agree_with_field_by_field_code_{}(\n        \
                 bytes in proptest::collection::vec(any::<u8>(), {size})\n    ) {{\n        \
                 agree::<{name}>(&bytes);\n    }}\n",
                name.to_lowercase()
            )
            .unwrap();
        }
        w.push_str("}\n");
        w
    }
}
