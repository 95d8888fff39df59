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
fn neighbours_of_one_width_join_and_write_the_same_bytes() {
    let from = Plain {
        word: 0x1234,
        flags: [true, false, true, true, false, true],
        wide: u64::MAX - 5,
    };
    let at = core::mem::offset_of!(Plain, flags);
    // SAFETY: each is one of `flags`' bools, at its offset in the `#[repr(C)]` struct.
    let bools: Vec<PlacedBytes<Plain>> = (0..6)
        .flat_map(|k| stores(unsafe { StructPlace::whole(at + k, 1) }, &from))
        .collect();
    let two = bools[0]
        .join(bools[1])
        .expect("side by side, one byte each");
    let four = two
        .join(bools[2].join(bools[3]).unwrap())
        .expect("two and two");
    assert_eq!((four.offset(), four.len()), (at, 4));
    assert!(bools[1].join(bools[0]).is_none(), "not in memory order");
    assert!(bools[0].join(bools[2]).is_none(), "not side by side");
    assert!(four.join(bools[4]).is_none(), "not of one width");
    let mut into = Plain::default();
    four.write(&mut into);
    bools[4].join(bools[5]).unwrap().write(&mut into);
    assert_eq!(into.flags, from.flags);
    assert_eq!((into.word, into.wide), (0, 0), "nothing beside the bools");
    // SAFETY: `wide` is a `u64` at its offset.
    let wide = unsafe { StructPlace::whole(core::mem::offset_of!(Plain, wide), 8) };
    let eight = stores(wide, &from);
    assert!(
        eight[0].join(eight[0]).is_none(),
        "eight bytes is the widest"
    );
    eight[0].write(&mut into);
    assert_eq!(into.wide, from.wide);
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
