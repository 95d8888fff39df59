//! What `#[derive(GlobalMemory)]` generates, pinned: layout, metadata, bit packing, get/set,
//! `Default`, located variables, and round trips over random values.

// Tests set one field after `Default` on purpose: that is how a program writes its variables.
#![allow(clippy::field_reassign_with_default)]

use plc_core::{
    Access, Direction, FixedString, GlobalMemory, IecType, ProcessImage, SetError, Value,
    ValueError,
};
use proptest::prelude::*;
use zerocopy::IntoBytes;
use zerocopy::byteorder::little_endian::{F32, F64, I32, U16};

/// The example variables of the JSON variable-list format, as a control program declares them.
#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Gm {
    /// Digital inputs of the IO module
    #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "input")]
    pub impact67_0_digital_inputs: u16,
    #[plc(link = "ethercat.impact67_0.digital_outputs", direction = "output")]
    pub impact67_0_digital_outputs: u16,
    #[plc(source = "impact67_0_digital_inputs", bit = 0)]
    pub ls_centering_neg: bool,
    #[plc(source = "impact67_0_digital_inputs", bit = 1)]
    pub ls_centering_pos: bool,
    #[plc(source = "impact67_0_digital_inputs", bit = 2)]
    pub ls_lift_neg: bool,
    #[plc(source = "impact67_0_digital_outputs", bit = 0)]
    pub cr_lift_brake: bool,
    #[plc(description = "Test identifier", initial = "TEST-001")]
    pub info_test_id: FixedString<64>,
    /// Specimen name,
    ///   as typed by the operator
    pub info_specimen_name: FixedString<128>,
    #[plc(nonvolatile, initial = 12.5, read_only)]
    pub press_home_offset_mm: f64,
    #[plc(name = "SpeedSetpoint", initial = -3, direction = "command")]
    pub speed: i32,
    pub recipe_speeds: [[f32; 4]; 3],
}

type Image = <Gm as GlobalMemory>::Image;

/// `Gm`'s image as `GlobalMemory::Image` documents it: a `#[repr(C)]` struct of the stored forms in
/// declaration order. The derive's image is a byte array; it must have exactly these bytes.
#[derive(zerocopy::IntoBytes, zerocopy::Immutable)]
#[repr(C)]
struct ReferenceImage {
    impact67_0_digital_inputs: U16,
    impact67_0_digital_outputs: U16,
    ls_centering_neg: u8,
    ls_centering_pos: u8,
    ls_lift_neg: u8,
    cr_lift_brake: u8,
    info_test_id: FixedString<64>,
    info_specimen_name: FixedString<128>,
    press_home_offset_mm: F64,
    speed: I32,
    recipe_speeds: [[F32; 4]; 3],
}

impl ReferenceImage {
    fn of(gm: &Gm) -> Self {
        ReferenceImage {
            impact67_0_digital_inputs: gm.impact67_0_digital_inputs.into(),
            impact67_0_digital_outputs: gm.impact67_0_digital_outputs.into(),
            ls_centering_neg: gm.ls_centering_neg.into(),
            ls_centering_pos: gm.ls_centering_pos.into(),
            ls_lift_neg: gm.ls_lift_neg.into(),
            cr_lift_brake: gm.cr_lift_brake.into(),
            info_test_id: gm.info_test_id,
            info_specimen_name: gm.info_specimen_name,
            press_home_offset_mm: gm.press_home_offset_mm.into(),
            speed: gm.speed.into(),
            recipe_speeds: gm.recipe_speeds.map(|row| row.map(F32::from)),
        }
    }
}

#[test]
fn offsets_are_those_of_the_reference_struct_and_there_is_no_padding() {
    let offsets = [
        core::mem::offset_of!(ReferenceImage, impact67_0_digital_inputs),
        core::mem::offset_of!(ReferenceImage, impact67_0_digital_outputs),
        core::mem::offset_of!(ReferenceImage, ls_centering_neg),
        core::mem::offset_of!(ReferenceImage, ls_centering_pos),
        core::mem::offset_of!(ReferenceImage, ls_lift_neg),
        core::mem::offset_of!(ReferenceImage, cr_lift_brake),
        core::mem::offset_of!(ReferenceImage, info_test_id),
        core::mem::offset_of!(ReferenceImage, info_specimen_name),
        core::mem::offset_of!(ReferenceImage, press_home_offset_mm),
        core::mem::offset_of!(ReferenceImage, speed),
        core::mem::offset_of!(ReferenceImage, recipe_speeds),
    ];
    let vars = Gm::VARIABLES;
    assert_eq!(vars.len(), offsets.len());
    let mut next = 0;
    for (v, offset) in vars.iter().zip(offsets) {
        assert_eq!(v.offset, offset, "{}", v.name);
        assert_eq!(v.offset, next, "{} follows the previous variable", v.name);
        next += v.size;
    }
    assert_eq!(core::mem::size_of::<Image>(), next);
    assert_eq!(core::mem::size_of::<ReferenceImage>(), next);
    assert_eq!(core::mem::align_of::<Image>(), 1);
    assert_eq!(next, 2 + 2 + 4 + 64 + 128 + 8 + 4 + 48);
}

#[test]
fn the_image_has_the_bytes_of_the_reference_struct() {
    let mut gm = Gm::default();
    gm.impact67_0_digital_inputs = 0xA5C3;
    gm.impact67_0_digital_outputs = 0x0102;
    gm.unpack_bits();
    gm.info_specimen_name.set("S-17");
    gm.recipe_speeds[2][3] = -0.25;
    gm.recipe_speeds[0][1] = 7.5;
    assert_eq!(gm.to_image().as_bytes(), ReferenceImage::of(&gm).as_bytes());
    let mut image = gm.to_image();
    gm.speed = 123_456;
    gm.store_image(&mut image);
    assert_eq!(image.as_bytes(), ReferenceImage::of(&gm).as_bytes());
}

#[test]
fn metadata_of_each_variable() {
    let v = Gm::VARIABLES;
    assert_eq!(v[0].description, "Digital inputs of the IO module");
    assert_eq!(v[0].link, Some("ethercat.impact67_0.digital_inputs"));
    assert_eq!(
        (v[0].iec_type, v[0].direction),
        (IecType::Uint, Direction::Input)
    );
    assert_eq!(v[2].bit.map(|b| (b.source, b.bit)), Some((0, 0)));
    assert_eq!(v[5].bit.map(|b| (b.source, b.bit)), Some((1, 0)));
    assert_eq!(
        v[2].direction,
        Direction::Input,
        "a mapped bool takes its source's direction"
    );
    assert_eq!(v[5].direction, Direction::Output);
    assert_eq!(v[6].initial, Some("\"TEST-001\""));
    assert_eq!(v[6].description, "Test identifier");
    assert_eq!(v[7].description, "Specimen name, as typed by the operator");
    assert_eq!(v[7].rust_type, "FixedString<128>");
    assert_eq!(v[7].string_capacity(), 128);
    assert!(v[8].nonvolatile && v[8].access == Access::ReadOnly);
    assert_eq!(v[8].initial, Some("12.5"));
    assert_eq!((v[9].name, v[9].initial), ("SpeedSetpoint", Some("-3")));
    assert_eq!(v[9].direction, Direction::Command);
    assert_eq!(
        (v[10].dims, v[10].rust_type),
        (&[3usize, 4][..], "[[f32; 4]; 3]")
    );
    assert_eq!(v[10].elements(), 12);
    assert_eq!(v[10].direction, Direction::Internal);
}

#[test]
fn layout_hash_follows_the_documented_recipe() {
    let mut h = plc_rules::layout::LayoutHasher::new();
    for v in Gm::VARIABLES {
        let bit = v.bit.map(|b| (b.source, b.bit));
        h = h.var(v.name, v.iec_type.name(), v.offset, v.size, v.dims, bit);
    }
    assert_eq!(Gm::LAYOUT_HASH, h.finish());
    assert_eq!(Gm::LAYOUT_HASH, plc_core::layout_hash(Gm::VARIABLES));
}

#[test]
fn default_takes_initials_and_packs_bools() {
    let gm = Gm::default();
    assert_eq!(gm.info_test_id, "TEST-001");
    assert_eq!((gm.press_home_offset_mm, gm.speed), (12.5, -3));
    assert!(gm.info_specimen_name.is_empty());
    assert_eq!(gm.recipe_speeds, [[0.0; 4]; 3]);
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Initials {
    #[plc(initial = 0b1010)]
    flags: u8,
    #[plc(source = "flags", bit = 1)]
    from_word: bool,
    #[plc(source = "flags", bit = 3, initial = false)]
    bool_wins: bool,
    #[plc(source = "flags", bit = 0, initial = true)]
    bool_sets: bool,
    #[plc(initial = 2.5)]
    table: [f32; 3],
}

#[test]
fn a_bools_initial_wins_for_its_bit_and_others_take_the_words() {
    let gm = Initials::default();
    assert!(gm.from_word, "bit 1 of the word's initial reaches the bool");
    assert!(!gm.bool_wins && gm.bool_sets);
    assert_eq!(gm.flags, 0b0011);
    assert_eq!(gm.table, [2.5; 3], "a scalar initial fills an array");
}

#[test]
fn unpack_and_pack_move_only_mapped_bits() {
    let mut gm = Gm::default();
    gm.impact67_0_digital_inputs = 0b1111_0000_0000_0101;
    gm.unpack_bits();
    assert!(gm.ls_centering_neg && !gm.ls_centering_pos && gm.ls_lift_neg);
    gm.impact67_0_digital_outputs = 0xFF00;
    gm.cr_lift_brake = true;
    gm.pack_bits();
    assert_eq!(
        gm.impact67_0_digital_outputs, 0xFF01,
        "unmapped bits are preserved"
    );
}

#[test]
fn set_keeps_bools_and_words_consistent_both_ways() {
    let mut gm = Gm::default();
    let word = Gm::index_of("impact67_0_digital_inputs").unwrap();
    gm.set(word, 0, Value::UInt(0b110)).unwrap();
    assert!(!gm.ls_centering_neg && gm.ls_centering_pos && gm.ls_lift_neg);
    let brake = Gm::index_of("CR_LIFT_BRAKE").unwrap();
    gm.impact67_0_digital_outputs = 0x8000;
    gm.set(brake, 0, Value::Bool(true)).unwrap();
    assert_eq!(gm.impact67_0_digital_outputs, 0x8001);
    assert_eq!(gm.get(brake, 0), Value::Bool(true));
}

#[test]
fn set_refuses_bad_values_and_changes_nothing() {
    let mut gm = Gm::default();
    let before = gm.clone();
    let speed = Gm::index_of("speedsetpoint").unwrap();
    let id = Gm::index_of("info_test_id").unwrap();
    let table = Gm::index_of("recipe_speeds").unwrap();
    assert_eq!(
        gm.set(speed, 0, Value::Text(FixedString::from_str_truncate("x"))),
        Err(SetError::Value {
            name: "SpeedSetpoint",
            error: ValueError::WrongKind {
                expected: IecType::Dint,
                found: "text"
            }
        })
    );
    assert!(matches!(
        gm.set(speed, 0, Value::Int(i64::MAX)),
        Err(SetError::Value {
            error: ValueError::OutOfRange { .. },
            ..
        })
    ));
    let long = Value::Text(FixedString::from_str_truncate(&"x".repeat(65)));
    assert_eq!(
        gm.set(id, 0, long),
        Err(SetError::Value {
            name: "info_test_id",
            error: ValueError::TooLong {
                len: 65,
                capacity: 64
            }
        })
    );
    assert_eq!(
        gm.set(table, 12, Value::Real(1.0)),
        Err(SetError::ElementOutOfRange {
            name: "recipe_speeds",
            element: 12,
            len: 12
        })
    );
    assert_eq!(
        gm.set(99, 0, Value::Bool(true)),
        Err(SetError::UnknownIndex { index: 99 })
    );
    assert_eq!(gm, before);
    assert_eq!(
        gm.set(
            id,
            0,
            Value::Text(FixedString::from_str_truncate("TEST-002"))
        ),
        Ok(())
    );
    gm.set(table, 5, Value::Int(7)).unwrap();
    assert_eq!(gm.recipe_speeds[1][1], 7.0);
    assert_eq!(gm.try_get(table, 12), None);
    assert_eq!(Gm::index_of("nonexistent"), None);
}

#[test]
fn the_image_is_little_endian_with_bools_as_bytes() {
    let mut gm = Gm::default();
    gm.impact67_0_digital_inputs = 0x1234;
    gm.ls_centering_pos = true;
    let image = gm.to_image();
    let bytes = image.as_bytes();
    assert_eq!(&bytes[0..2], &[0x34, 0x12]);
    assert_eq!(bytes[5], 1, "ls_centering_pos follows two words and a bool");
    assert_eq!(&bytes[8..16], b"TEST-001");
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Located {
    #[plc(at = "%IW4")]
    analog_in: i16,
    #[plc(at = "%IX0.3")]
    start_button: bool,
    #[plc(at = "%QD0")]
    valve_setpoint: f32,
    #[plc(at = "%QX4.1")]
    horn: bool,
    internal: u8,
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
#[plc(byte_order = "little", unaligned)]
pub struct LocatedLittle {
    #[plc(at = "%IW1")]
    analog_in: u16,
}

#[test]
fn located_variables_read_and_write_by_address() {
    let pii = [0b0000_1000u8, 0, 0, 0, 0xFF, 0xFE];
    let mut gm = Located::default();
    gm.read_inputs(&ProcessImage::new(&pii[..])).unwrap();
    assert_eq!((gm.analog_in, gm.start_button), (-2, true));
    gm.valve_setpoint = 1.5;
    gm.horn = true;
    let mut piq = [0u8; 5];
    piq[4] = 0b1000_0000;
    gm.write_outputs(&mut ProcessImage::new(&mut piq[..]))
        .unwrap();
    assert_eq!(piq, [0x3F, 0xC0, 0, 0, 0b1000_0010]);
    let short = [0u8; 2];
    assert!(gm.read_inputs(&ProcessImage::new(&short[..])).is_err());

    let mut little = LocatedLittle::default();
    little
        .read_inputs(&ProcessImage::new(&[0u8, 0x34, 0x12][..]))
        .unwrap();
    assert_eq!(
        little.analog_in, 0x1234,
        "the declaration's byte order and alignment apply"
    );
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Everything {
    a: bool,
    b: i8,
    c: i16,
    d: i32,
    e: i64,
    f: u8,
    g: u16,
    h: u32,
    i: u64,
    j: f32,
    k: f64,
    l: FixedString<12>,
    m: [[i16; 2]; 3],
    n: [bool; 3],
}

fn text() -> impl Strategy<Value = FixedString<12>> {
    "\\PC{0,12}".prop_map(|s| FixedString::from_str_truncate(&s))
}

proptest! {
    #[test]
    fn from_image_of_to_image_is_identity(
        a: bool, b: i8, c: i16, d: i32, e: i64, f: u8, g: u16, h: u32, i: u64,
        j in any::<f32>().prop_filter("NaN is not equal to itself", |x| !x.is_nan()),
        k in any::<f64>().prop_filter("NaN is not equal to itself", |x| !x.is_nan()),
        l in text(), m: [[i16; 2]; 3], n: [bool; 3],
    ) {
        let x = Everything { a, b, c, d, e, f, g, h, i, j, k, l, m, n };
        prop_assert_eq!(Everything::from_image(&x.to_image()), x.clone());
        let mut y = Everything::default();
        y.load_image(&x.to_image());
        prop_assert_eq!(y, x);
    }

    #[test]
    fn pack_then_unpack_preserves_unmapped_bits(
        inputs: u16, outputs: u16, brake: bool
    ) {
        let mut gm = Gm { impact67_0_digital_inputs: inputs, ..Gm::default() };
        gm.unpack_bits();
        prop_assert_eq!(gm.ls_centering_neg, inputs & 1 != 0);
        prop_assert_eq!(gm.ls_lift_neg, inputs & 4 != 0);
        gm.pack_bits();
        prop_assert_eq!(gm.impact67_0_digital_inputs, inputs);
        gm.impact67_0_digital_outputs = outputs;
        gm.cr_lift_brake = brake;
        gm.pack_bits();
        prop_assert_eq!(gm.impact67_0_digital_outputs, (outputs & !1) | brake as u16);
    }
}

type Word = u16;
type Flag = bool;
type Label = FixedString<4>;

/// Fields declared through aliases: the derive only sees paths, the compiler knows the types.
#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Aliased {
    #[plc(initial = 0x8001, iec_type = "WORD")]
    w: Word,
    #[plc(source = "w", bit = 15)]
    top: Flag,
    #[plc(initial = "ok")]
    label: Label,
}

#[test]
fn alias_fields_behave_like_the_types_they_name() {
    let mut gm = Aliased::default();
    assert!(gm.top, "bit 15 of the initial 0x8001");
    assert_eq!(gm.label.as_str(), "ok");
    let v = Aliased::VARIABLES;
    assert_eq!((v[0].iec_type, v[0].size), (IecType::Word, 2));
    assert_eq!(v[1].bit.map(|b| (b.source, b.bit)), Some((0, 15)));
    assert_eq!(v[2].offset, 2 + 1, "after the word and the bool");
    gm.set(1, 0, Value::Bool(false)).expect("bool");
    assert_eq!(gm.w, 0x0001, "the bool's bit reached its word");
    gm.set(0, 0, Value::UInt(0x8000)).expect("word");
    assert!(gm.top, "the word's bit reached its bool");
    assert_eq!(Aliased::from_image(&gm.to_image()), gm);
}

type Lreal = f64;

/// Bare integers on reals (IEC 61131-3), beyond the integer types included.
#[derive(GlobalMemory, Debug)]
pub struct BareIntegers {
    #[plc(initial = 100000000000000000000)]
    above_u64: f64,
    #[plc(initial = -100000000000000000000)]
    below_i64: f64,
    #[plc(initial = 100000000000000000000)]
    above_u64_alias: Lreal,
    #[plc(initial = 1000000000000000000000000000000000000000000)]
    above_i128: f64,
    #[plc(initial = 18446744073709551615)]
    u64_max_on_f32: f32,
}

#[test]
fn bare_integer_initials_on_reals_keep_their_value_beyond_u64() {
    let gm = BareIntegers::default();
    assert_eq!(gm.above_u64, 1e20);
    assert_eq!(gm.below_i64, -1e20);
    assert_eq!(gm.above_u64_alias, 1e20);
    assert_eq!(gm.above_i128, 1e42);
    assert_eq!(gm.u64_max_on_f32, 18446744073709551615u64 as f32);
    let initial = |i: usize| BareIntegers::VARIABLES[i].initial;
    assert_eq!(initial(0), Some("100000000000000000000"));
    assert_eq!(initial(1), Some("-100000000000000000000"));
    assert_eq!(
        initial(3),
        Some("1000000000000000000000000000000000000000000")
    );
}
