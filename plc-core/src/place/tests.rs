use super::*;

/// A plain struct with a known layout, for places made by hand (as the derive would).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Plain {
    word: u16,
    flags: [bool; 6],
    wide: u64,
}

fn stores(place: StructPlace<Plain>, from: &Plain) -> Vec<PlacedBytes<Plain>> {
    let mut out = Vec::new();
    assert!(place.capture(from, |p| out.push(p)));
    out
}

#[test]
fn a_bit_is_one_masked_byte_and_leaves_the_others() {
    // SAFETY: `word` is a `u16` at its `offset_of!`.
    let bit = unsafe { StructPlace::<Plain>::bit_of(core::mem::offset_of!(Plain, word), 2, 11) };
    let from = Plain {
        word: 1 << 11,
        ..Plain::default()
    };
    let s = stores(bit, &from);
    assert_eq!(s.len(), 1);
    let mut into = Plain {
        word: 0xf7ff,
        ..Plain::default()
    };
    s[0].write(&mut into);
    assert_eq!(into.word, 0xffff, "bit 11 set, no other touched");
    let cleared = stores(bit, &Plain::default());
    cleared[0].write(&mut into);
    assert_eq!(into.word, 0xf7ff);
}

#[test]
fn held_bytes_write_each_byte_once_the_last_store_winning() {
    let from = Plain {
        word: 0x1234,
        flags: [true, false, true, true, false, true],
        wide: u64::MAX - 5,
    };
    let (word, flags, wide) = (
        core::mem::offset_of!(Plain, word),
        core::mem::offset_of!(Plain, flags),
        core::mem::offset_of!(Plain, wide),
    );
    // SAFETY (all): each is a field of `Plain` at its offset (`flags` one bool each), or a bit
    // of its `u16`.
    let bools: Vec<PlacedBytes<Plain>> = (0..6)
        .flat_map(|k| stores(unsafe { StructPlace::whole(flags + k, 1) }, &from))
        .collect();
    let held = HeldBytes::new(bools.iter().copied());
    assert_eq!(
        held.stores(),
        2,
        "six bools side by side: four and two bytes"
    );
    let mut into = Plain::default();
    held.write(&mut into);
    assert_eq!(into.flags, from.flags);
    assert_eq!((into.word, into.wide), (0, 0), "nothing beside the bools");

    // A whole word, then a bit of it from another value: the bit wins; the other way round,
    // the word does. Bits of one byte from two stores make one masked store.
    let whole = stores(unsafe { StructPlace::whole(word, 2) }, &from);
    let bit = |b, v: &Plain| stores(unsafe { StructPlace::bit_of(word, 2, b) }, v);
    let zero = Plain::default();
    let bit_last = HeldBytes::new(whole.iter().chain(&bit(4, &zero)).copied());
    let word_last = HeldBytes::new(bit(4, &zero).iter().chain(&whole).copied());
    let (mut a, mut b) = (Plain::default(), Plain::default());
    bit_last.write(&mut a);
    word_last.write(&mut b);
    assert_eq!((a.word, b.word), (0x1224, 0x1234));
    let two_bits = HeldBytes::new(bit(0, &from).into_iter().chain(bit(1, &from)));
    assert_eq!(two_bits.stores(), 1);
    let mut c = Plain {
        word: 0xffff,
        ..Plain::default()
    };
    two_bits.write(&mut c);
    assert_eq!(c.word, 0xfffc, "bits 0 and 1 of 0x1234, no other touched");

    // Eight bytes in one store; a run of seven in three.
    let eight = stores(unsafe { StructPlace::whole(wide, 8) }, &from);
    let seven: Vec<_> = (0..7)
        .flat_map(|k| stores(unsafe { StructPlace::whole(wide + k, 1) }, &from))
        .collect();
    assert_eq!(HeldBytes::new(eight.iter().copied()).stores(), 1);
    assert_eq!(HeldBytes::new(seven.iter().copied()).stores(), 3);
    let mut d = Plain::default();
    HeldBytes::new(seven).write(&mut d);
    assert_eq!(d.wide, from.wide & 0x00ff_ffff_ffff_ffff_u64.to_le());
}

#[test]
fn a_place_beyond_its_struct_is_never_read_or_written() {
    let size = core::mem::size_of::<Plain>();
    // SAFETY: not true, on purpose: `capture` checks what it can and refuses these.
    let beyond = [
        unsafe { StructPlace::<Plain>::whole(size - 1, 2) },
        unsafe { StructPlace::<Plain>::whole(usize::MAX, 2) },
        unsafe { StructPlace::<Plain>::whole(0, 0) },
        unsafe { StructPlace::<Plain>::bit_of(0, 2, 16) },
    ];
    for place in beyond {
        assert!(
            !place.capture(&Plain::default(), |_| panic!("captured {place:?}")),
            "{place:?}"
        );
    }
}

#[test]
fn an_array_places_its_items_and_a_leaf_beyond_it_has_no_place() {
    // [[u16; 3]; 2]: element 4 is [1][1], 4 u16 from the start.
    let mut n = 0;
    assert!(<[[u16; 3]; 2] as crate::PlcType>::__places(4, &mut |p| {
        assert_eq!((p.offset(), p.len()), (8, 2));
        n += 1;
    }));
    assert_eq!(n, 1);
    assert!(!<[u16; 3] as crate::PlcType>::__places(3, &mut |_| {}));
    assert!(!<bool as crate::PlcType>::__places(1, &mut |_| {}));
}
