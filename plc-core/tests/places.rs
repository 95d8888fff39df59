//! Where the derive says each basic value lies (`GlobalMemory::struct_places`): the bytes
//! captured there from a struct that holds a value, written into another, give exactly what a
//! `set` of that value gives, for every leaf of a struct of every shape.

use plc_core::place::{self, HeldBytes, PlacedBytes};
use plc_core::rules::path;
use plc_core::{FixedString, GlobalMemory, IecType, PlcStruct, Time, Value};
use proptest::prelude::*;
use std::mem::{offset_of, size_of};

#[derive(PlcStruct, Debug, Clone, PartialEq)]
struct Inner {
    flags: u8,
    #[plc(source = "flags", bit = 2)]
    ready: bool,
    #[plc(source = "flags", bit = 7)]
    fault: bool,
    pos: f64,
    name: FixedString<5>,
    grid: [[i16; 3]; 2],
}

#[derive(PlcStruct, Debug, Clone, PartialEq)]
struct Outer {
    id: u32,
    inner: Inner,
    pair: [Inner; 2],
    since: Time,
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
struct Shapes {
    lamp: bool,
    count8: u8,
    sbyte: i8,
    word16: u16,
    int16: i16,
    count32: u32,
    delta32: i32,
    count64: u64,
    delta64: i64,
    speed: f32,
    length: f64,
    one_char: FixedString<1>,
    text13: FixedString<13>,
    text255: FixedString<255>,
    elapsed: Time,
    status: u16,
    #[plc(source = "status", bit = 0)]
    w0: bool,
    #[plc(source = "status", bit = 9)]
    w9: bool,
    #[plc(source = "status", bit = 15)]
    w15: bool,
    big: i64,
    #[plc(source = "big", bit = 63)]
    top: bool,
    small: i8,
    #[plc(source = "small", bit = 7)]
    sign: bool,
    wide: u32,
    #[plc(source = "wide", bit = 17)]
    w17: bool,
    v1: [u8; 3],
    v2: [[f64; 2]; 3],
    v3: [[[u16; 2]; 2]; 2],
    texts: [FixedString<9>; 2],
    times: [Time; 2],
    bools: [bool; 5],
    inner: Inner,
    outers: [Outer; 2],
    deep: [[Inner; 2]; 2],
}

/// A small deterministic generator (xorshift), so a failure names its seed.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// A value that fits leaf `leaf` of variable `index`: anywhere in its type's range.
    fn value(&mut self, index: usize, leaf: usize) -> Value {
        let found = path::leaf(Shapes::VARIABLES, index, leaf).expect("a leaf");
        let var = found.node;
        let r = self.next();
        match var.iec_type {
            IecType::Bool => Value::Bool(r & 1 == 1),
            IecType::Real => Value::Real(f64::from((r as i32) as f32 / 7.0)),
            IecType::Lreal => Value::Real((r as i64) as f64 / 3.0),
            IecType::Ltime => Value::Time(Time::from_nanos(r as i64)),
            IecType::String => {
                let len = (r as usize) % (var.string_capacity() + 1);
                let text: String = (0..len)
                    .map(|k| char::from(b'a' + ((r >> (k % 60)) % 26) as u8))
                    .collect();
                Value::Text(FixedString::from_str_truncate(&text))
            }
            t => {
                let (lo, hi) = t.int_range().expect("an integer");
                let span = (hi - lo) as u128 + 1;
                let v = lo + ((u128::from(r) << 64 | u128::from(self.next())) % span) as i128;
                if lo < 0 {
                    Value::Int(v as i64)
                } else {
                    Value::UInt(v as u64)
                }
            }
        }
    }
}

/// Every (variable, leaf) of `Shapes`.
fn leaves() -> Vec<(usize, usize)> {
    Shapes::VARIABLES
        .iter()
        .enumerate()
        .flat_map(|(i, v)| (0..v.leaves()).map(move |l| (i, l)))
        .collect()
}

/// A `Shapes` with every value set at random (through `set`, so bit-mapped bools agree with
/// their words).
fn random_shapes(rng: &mut Rng) -> Shapes {
    let mut gm = Shapes::default();
    for (i, l) in leaves() {
        let v = rng.value(i, l);
        gm.set(i, l, v).expect("a value that fits");
    }
    gm
}

/// Sets each leaf in `from` to a new value, captures it, writes it into `into`, and checks
/// that `into` is then what a `set` of the value would have made of it.
fn each_leaf_written_at_its_place_is_a_set(seed: u64) {
    let mut rng = Rng(seed | 1);
    let from = random_shapes(&mut rng);
    let into = random_shapes(&mut rng);
    for (i, l) in leaves() {
        let v = rng.value(i, l);
        let mut holder = from.clone();
        holder.set(i, l, v).unwrap();
        let mut stores: Vec<PlacedBytes<Shapes>> = Vec::new();
        assert!(
            place::capture(&holder, i, l, |p| stores.push(p)),
            "no place for variable {i} leaf {l}"
        );
        let mut written = into.clone();
        for s in &stores {
            s.write(&mut written);
        }
        let mut expected = into.clone();
        expected.set(i, l, v).unwrap();
        assert_eq!(
            written, expected,
            "variable {i} leaf {l} = {v:?} (seed {seed})"
        );
        assert_eq!(written.get(i, l), holder.get(i, l));
    }
}

/// Captures a third of the leaves, in a shuffled order, each right after a `set` of a new
/// value into one struct (as the force table does), and checks that writing all their bytes
/// at once ([`HeldBytes`]) into another struct gives what `set`s in that order would.
fn many_values_held_at_once_are_sets_in_order(seed: u64) {
    let mut rng = Rng(seed | 1);
    let mut holder = random_shapes(&mut rng);
    let into = random_shapes(&mut rng);
    let mut chosen: Vec<(usize, usize)> = leaves()
        .into_iter()
        .filter(|_| rng.next().is_multiple_of(3))
        .collect();
    for k in (1..chosen.len()).rev() {
        chosen.swap(k, (rng.next() % (k as u64 + 1)) as usize);
    }
    let mut stores = Vec::new();
    let mut expected = into.clone();
    for &(i, l) in &chosen {
        let v = rng.value(i, l);
        holder.set(i, l, v).unwrap();
        assert!(place::capture(&holder, i, l, |p| stores.push(p)));
        expected.set(i, l, v).unwrap();
    }
    let held = HeldBytes::new(stores.iter().copied());
    assert!(held.stores() <= stores.len());
    let mut written = into.clone();
    held.write(&mut written);
    assert_eq!(written, expected, "{} values (seed {seed})", chosen.len());
}

#[test]
fn every_leaf_written_at_its_place_reads_back_as_set() {
    for seed in [1, 0x9e37_79b9_7f4a_7c15, 42] {
        each_leaf_written_at_its_place_is_a_set(seed);
        many_values_held_at_once_are_sets_in_order(seed);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn any_values_written_at_their_places_read_back_as_set(seed in any::<u64>()) {
        each_leaf_written_at_its_place_is_a_set(seed);
        many_values_held_at_once_are_sets_in_order(seed);
    }
}

/// The places, one per (variable, leaf), as `(offset, len, bit)`.
fn places_of(index: usize, leaf: usize) -> Vec<(usize, usize, Option<u8>)> {
    let mut out = Vec::new();
    assert!(Shapes::struct_places(index, leaf, &mut |p| out.push((
        p.offset(),
        p.len(),
        p.bit()
    ))));
    out
}

fn index(name: &str) -> usize {
    Shapes::index_of(name).unwrap()
}

#[test]
fn places_are_the_offsets_of_the_fields_through_structures_and_arrays() {
    assert_eq!(
        places_of(index("length"), 0),
        [(offset_of!(Shapes, length), 8, None)]
    );
    assert_eq!(
        places_of(index("text255"), 0),
        [(offset_of!(Shapes, text255), 255, None)]
    );
    // v3[1][0][1]: row-major element 5 of 2 x 2 x 2.
    assert_eq!(
        places_of(index("v3"), 5),
        [(offset_of!(Shapes, v3) + 5 * 2, 2, None)]
    );
    // outers[1].pair[0].pos: Outer's leaves are id (1), inner (11), pair (22), since (1); Inner's
    // are flags, ready, fault, pos, name, then 6 of grid.
    let inner_leaves = 11;
    let outer_leaves = 1 + inner_leaves + 2 * inner_leaves + 1;
    let leaf = outer_leaves + 1 + inner_leaves + 3;
    let at = offset_of!(Shapes, outers)
        + size_of::<Outer>()
        + offset_of!(Outer, pair)
        + offset_of!(Inner, pos);
    assert_eq!(places_of(index("outers"), leaf), [(at, 8, None)]);
    assert_eq!(
        Shapes::VARIABLES[index("outers")].leaves(),
        2 * outer_leaves
    );
}

#[test]
fn a_mapped_bool_also_writes_its_bit_and_a_source_word_its_bools() {
    assert_eq!(
        places_of(index("w9"), 0),
        [
            (offset_of!(Shapes, w9), 1, None),
            (offset_of!(Shapes, status), 2, Some(9)),
        ]
    );
    assert_eq!(
        places_of(index("status"), 0),
        [
            (offset_of!(Shapes, status), 2, None),
            (offset_of!(Shapes, w0), 1, None),
            (offset_of!(Shapes, w9), 1, None),
            (offset_of!(Shapes, w15), 1, None),
        ]
    );
    // Inside a structure, in an array: deep[1][0].fault, bit 7 of that Inner's flags.
    let inner = offset_of!(Shapes, deep) + 2 * size_of::<Inner>();
    assert_eq!(
        places_of(index("deep"), 2 * 11 + 2),
        [
            (inner + offset_of!(Inner, fault), 1, None),
            (inner + offset_of!(Inner, flags), 1, Some(7)),
        ]
    );
}

#[test]
fn values_that_do_not_exist_have_no_place() {
    let none = |i, l| !Shapes::struct_places(i, l, &mut |_| panic!("a place for {i}/{l}"));
    assert!(none(Shapes::VARIABLES.len(), 0));
    assert!(none(usize::MAX, 0));
    assert!(none(index("length"), 1));
    assert!(none(index("v2"), 6));
    assert!(none(index("deep"), 4 * 11));
    assert!(none(index("outers"), usize::MAX));
}

#[test]
fn a_string_is_written_in_pieces_that_join_back_to_its_bytes() {
    let mut gm = Shapes::default();
    let i = index("text13");
    gm.set(
        i,
        0,
        Value::Text(FixedString::from_str_truncate("abcdefghijklm")),
    )
    .unwrap();
    let mut stores = Vec::new();
    assert!(place::capture(&gm, i, 0, |p| stores.push(p)));
    let lens: Vec<usize> = stores.iter().map(PlacedBytes::len).collect();
    assert_eq!(lens, [8, 4, 1], "13 bytes as 8 + 4 + 1");
    let mut other = Shapes::default();
    stores.iter().for_each(|s| s.write(&mut other));
    assert_eq!(other.text13, "abcdefghijklm");
    assert_eq!(other, gm);
}
