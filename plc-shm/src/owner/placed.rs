//! Where a forced value lies in the program's struct: the bytes `set` wrote for it, captured
//! when it was forced (see [`plc_core::place`]). Nearly every value is one store (a number,
//! a BOOL's bit or byte), kept inline so a flood of forces allocates nothing per value; a
//! STRING is several.

use plc_core::memory::Memory;
use plc_core::place::PlacedBytes;

/// The bytes that hold a forced value where it lies in `T`.
#[derive(Clone, Debug)]
pub(crate) enum Placed<T> {
    /// `T` does not say where the value lies (written by hand): `set` holds it.
    Unplaced,
    /// One store.
    One(PlacedBytes<T>),
    /// Several stores, in the order `capture` gave them.
    Many(Vec<PlacedBytes<T>>),
}

impl<T: Memory> Placed<T> {
    /// The bytes that hold value `leaf` of variable `index` where it lies in `gm`, which holds
    /// its forced value.
    pub fn capture(gm: &T, index: usize, leaf: usize) -> Self {
        let mut placed = Placed::Unplaced;
        let whole = gm.capture_places(index, leaf, |s| {
            placed = match std::mem::replace(&mut placed, Placed::Unplaced) {
                Placed::Unplaced => Placed::One(s),
                Placed::One(first) => Placed::Many(vec![first, s]),
                Placed::Many(mut v) => {
                    v.push(s);
                    Placed::Many(v)
                }
            };
        });
        if whole { placed } else { Placed::Unplaced }
    }
}

/// The same stores (a re-force to the value held changes nothing the cycle writes).
impl<T> PartialEq for Placed<T> {
    fn eq(&self, other: &Self) -> bool {
        self.is_placed() == other.is_placed() && self.stores() == other.stores()
    }
}

impl<T> Placed<T> {
    /// Whether `T` said where the value lies.
    pub fn is_placed(&self) -> bool {
        !matches!(self, Placed::Unplaced)
    }

    /// Its stores (none if unplaced).
    pub fn stores(&self) -> &[PlacedBytes<T>] {
        match self {
            Placed::Unplaced => &[],
            Placed::One(s) => std::slice::from_ref(s),
            Placed::Many(v) => v,
        }
    }
}
