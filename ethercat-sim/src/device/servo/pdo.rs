//! The process image as the PDO assignment (0x1C12, 0x1C13) and mappings say: where each
//! mapped object sits in the output and input SyncManager areas, and copying between those
//! areas and the object dictionary. The layout is read from the dictionary each cycle, so
//! a program that remaps PDOs by SDO in PRE-OP gets the image it mapped.

use super::objects;
use crate::coe::Dictionary;
use std::ops::Range;

/// More PDOs or entries than this are not read (a corrupt count must not loop long).
const MAX_ITEMS: u32 = 64;

/// One mapped object: its index and sub-index, first byte in the area and length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Slot {
    index: u16,
    sub: u8,
    offset: usize,
    bytes: usize,
}

/// The objects the PDOs assigned in `assignment` (0x1C12 or 0x1C13) map, in order. Entries
/// of a bit length that is not whole bytes, or that follow one, are left out: ethercrab
/// maps whole bytes, and bit-granular mapping is not simulated.
pub(crate) fn layout(d: &Dictionary, assignment: u16) -> Vec<Slot> {
    let mut slots = Vec::new();
    let mut bit = 0usize;
    let pdos = d.get(assignment, 0).unwrap_or(0).min(MAX_ITEMS);
    for i in 1..=pdos {
        let Some(pdo) = d.get(assignment, i as u8) else {
            continue;
        };
        let entries = d.get(pdo as u16, 0).unwrap_or(0).min(MAX_ITEMS);
        for j in 1..=entries {
            let mapping = d.get(pdo as u16, j as u8).unwrap_or(0);
            let bits = (mapping & 0xFF) as usize;
            if bits.is_multiple_of(8) && bit.is_multiple_of(8) && bits > 0 {
                slots.push(Slot {
                    index: (mapping >> 16) as u16,
                    sub: (mapping >> 8) as u8,
                    offset: bit / 8,
                    bytes: (bits / 8).min(4),
                });
            }
            bit += bits;
        }
    }
    slots
}

/// Takes the objects `slots` map from the output bytes `area` of `mem` into the dictionary.
pub(crate) fn receive(d: &mut Dictionary, slots: &[Slot], mem: &[u8], area: Range<usize>) {
    for s in slots {
        let start = area.start + s.offset;
        let Some(bytes) = mem.get(start..start + s.bytes) else {
            continue;
        };
        if start + s.bytes > area.end {
            continue;
        }
        let mut le = [0u8; 4];
        le[..bytes.len()].copy_from_slice(bytes);
        objects::store(d, s.index, s.sub, u32::from_le_bytes(le));
    }
}

/// Puts the objects `slots` map from the dictionary into the input bytes `area` of `mem`
/// (0 for an object the model does not have).
pub(crate) fn transmit(d: &Dictionary, slots: &[Slot], mem: &mut [u8], area: Range<usize>) {
    for s in slots {
        let start = area.start + s.offset;
        if start + s.bytes > area.end {
            continue;
        }
        let value = d.get(s.index, s.sub).unwrap_or(0).to_le_bytes();
        if let Some(out) = mem.get_mut(start..start + s.bytes) {
            out.copy_from_slice(&value[..s.bytes]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_preset_image_has_the_documented_layout() {
        let d = objects::akd(0x6A, 0x0041_4B44, 2, 0);
        let rx: Vec<(u16, usize, usize)> = layout(&d, 0x1C12)
            .iter()
            .map(|s| (s.index, s.offset, s.bytes))
            .collect();
        assert_eq!(
            rx,
            [
                (0x6040, 0, 2),
                (0x6060, 2, 1),
                (0x607A, 3, 4),
                (0x60FF, 7, 4)
            ]
        );
        let tx = layout(&d, 0x1C13);
        let last = tx.last().map(|s| (s.index, s.offset + s.bytes));
        assert_eq!((tx.len(), last), (6, Some((0x603F, 17))));
    }

    #[test]
    fn an_area_too_short_for_the_mapping_is_filled_as_far_as_it_goes() {
        let d = objects::akd(0x6A, 0x0041_4B44, 2, 0);
        let mut mem = vec![0xAAu8; 8];
        transmit(&d, &layout(&d, 0x1C13), &mut mem, 2..5);
        assert_eq!(mem, [0xAA, 0xAA, 0, 0, 0, 0xAA, 0xAA, 0xAA]);
    }
}
