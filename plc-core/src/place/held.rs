//! [`HeldBytes`]: the bytes of many values held at their places (a program's forces), each
//! byte once, written with as few stores as the bytes allow.

use super::PlacedBytes;
use core::marker::PhantomData;

/// The bytes a list of [`PlacedBytes`] writes into an `S`, in their order, made into one
/// store per run of 8, 4, 2 or 1 whole bytes side by side and a masked store per byte only
/// some of whose bits are held. Each byte is written once, with what the last of the list to
/// write it gave: where two overlap (a forced source word and then one of its forced bools)
/// the later wins, as it would writing them in order. The stores of one width are written in
/// one loop of their own, with no branch on the width.
///
/// ```
/// use plc_core::place::{self, HeldBytes};
/// use plc_core::{GlobalMemory, Value};
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     lights: u8,
///     #[plc(source = "lights", bit = 0)]
///     red: bool,
///     #[plc(source = "lights", bit = 7)]
///     green: bool,
/// }
/// let mut gm = Gm::default();
/// let mut stores = Vec::new();
/// gm.set(0, 0, Value::UInt(0x81)).unwrap();
/// assert!(place::capture(&gm, 0, 0, |s| stores.push(s)));
/// gm.set(2, 0, Value::Bool(false)).unwrap();
/// assert!(place::capture(&gm, 2, 0, |s| stores.push(s)));
/// let held = HeldBytes::new(stores);
/// let mut other = Gm::default();
/// held.write(&mut other);
/// assert_eq!((other.lights, other.red, other.green), (0x01, true, false));
/// ```
pub struct HeldBytes<S> {
    eights: Vec<(u32, u64)>,
    fours: Vec<(u32, u32)>,
    twos: Vec<(u32, u16)>,
    ones: Vec<(u32, u8)>,
    /// `(offset, mask, bits)`.
    masked: Vec<(u32, u8, u8)>,
    _in: PhantomData<fn() -> S>,
}

impl<S> Default for HeldBytes<S> {
    fn default() -> Self {
        HeldBytes {
            eights: Vec::new(),
            fours: Vec::new(),
            twos: Vec::new(),
            ones: Vec::new(),
            masked: Vec::new(),
            _in: PhantomData,
        }
    }
}

impl<S> HeldBytes<S> {
    /// The bytes `stores` write, in their order.
    pub fn new(stores: impl IntoIterator<Item = PlacedBytes<S>>) -> Self {
        // Every byte written, in the stores' order: sorted by offset by a stable sort (so
        // of one offset's bytes the last store's wins), which is nearly free on bytes that
        // come in order, as a program's values forced in declaration order do. Offsets fit
        // in a u32: `capture` checked every place's end against `u32::MAX`.
        let stores = stores.into_iter();
        let mut bytes: Vec<(u32, u8, u8)> = Vec::with_capacity(stores.size_hint().0);
        for store in stores {
            store.each_byte(|offset, mask, bits| bytes.push((offset as u32, mask, bits)));
        }
        bytes.sort_by_key(|&(offset, ..)| offset);
        let mut merged: Vec<(usize, u8, u8)> = Vec::with_capacity(bytes.len());
        for (offset, mask, bits) in bytes {
            let offset = offset as usize;
            match merged.last_mut() {
                Some((at, held, value)) if *at == offset => {
                    *value = (*value & !mask) | (bits & mask);
                    *held |= mask;
                }
                _ => merged.push((offset, mask, bits & mask)),
            }
        }
        let mut out = HeldBytes::default();
        let mut k = 0;
        while k < merged.len() {
            let (offset, mask, bits) = merged[k];
            if mask != 0xff {
                out.masked.push((offset as u32, mask, bits));
                k += 1;
                continue;
            }
            // The run of whole bytes side by side from here (up to the widest store: a run
            // is looked at eight bytes at a time, never counted to its end), cut into the
            // widest stores.
            let run = merged[k..]
                .iter()
                .take(8)
                .enumerate()
                .take_while(|&(n, &(at, held, _))| at == offset + n && held == 0xff)
                .count();
            let width = [8, 4, 2, 1].into_iter().find(|&w| w <= run).unwrap_or(1);
            let mut piece = [0u8; 8];
            for (n, byte) in piece.iter_mut().take(width).enumerate() {
                *byte = merged[k + n].2;
            }
            // Offsets fit: each byte came from a place `capture` checked against `u32::MAX`.
            let at = offset as u32;
            match width {
                8 => out.eights.push((at, u64::from_ne_bytes(piece))),
                4 => out.fours.push((
                    at,
                    u32::from_ne_bytes([piece[0], piece[1], piece[2], piece[3]]),
                )),
                2 => out
                    .twos
                    .push((at, u16::from_ne_bytes([piece[0], piece[1]]))),
                _ => out.ones.push((at, piece[0])),
            }
            k += width;
        }
        out
    }

    /// How many stores [`write`](Self::write) makes.
    pub fn stores(&self) -> usize {
        self.eights.len() + self.fours.len() + self.twos.len() + self.ones.len() + self.masked.len()
    }

    /// Whether nothing is held.
    pub fn is_empty(&self) -> bool {
        self.stores() == 0
    }

    /// Writes every byte held into `to`.
    #[inline]
    pub fn write(&self, to: &mut S) {
        let base = (to as *mut S).cast::<u8>();
        // SAFETY (all five loops): every byte written was written by a `PlacedBytes<S>`, made
        // by `capture` from a place that lies inside `S`; its value is the one that store, or
        // the last of several, gave it: a byte read from the same offset of another `S`, in
        // the field the place's maker proved there (valid: any byte is, but a bool's, which
        // is written whole from a bool), or bits masked into a byte of an integer. A store of
        // several bytes covers only bytes held, side by side. The `&mut S` makes the writes
        // exclusive; they are unaligned.
        unsafe {
            for &(at, v) in &self.eights {
                base.add(at as usize).cast::<u64>().write_unaligned(v);
            }
            for &(at, v) in &self.fours {
                base.add(at as usize).cast::<u32>().write_unaligned(v);
            }
            for &(at, v) in &self.twos {
                base.add(at as usize).cast::<u16>().write_unaligned(v);
            }
            for &(at, v) in &self.ones {
                base.add(at as usize).write(v);
            }
            for &(at, mask, bits) in &self.masked {
                let p = base.add(at as usize);
                p.write((p.read() & !mask) | bits);
            }
        }
    }
}
