//! Map keys for the checker's lookups. A declaration's names are short and not chosen by an
//! attacker who could aim at collisions, so FNV-1a (the layout hash's function) is enough and
//! several times faster than the default SipHash; names compare case-insensitively without
//! allocating a lower-case copy of each.

use core::hash::{BuildHasherDefault, Hash, Hasher};
use std::collections::HashMap;

/// FNV-1a 64, as a `Hasher`.
pub(super) struct Fnv(u64);

impl Default for Fnv {
    fn default() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
}

impl Hasher for Fnv {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

/// A `HashMap` hashed with [`Fnv`].
pub(super) type FnvMap<K, V> = HashMap<K, V, BuildHasherDefault<Fnv>>;

/// A name compared and hashed case-insensitively (ASCII), as declaration names compare.
#[derive(Clone, Copy, Debug)]
pub(super) struct NoCase<'a>(pub(super) &'a str);

impl PartialEq for NoCase<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.0.eq_ignore_ascii_case(other.0)
    }
}

impl Eq for NoCase<'_> {}

impl Hash for NoCase<'_> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        for b in self.0.bytes() {
            state.write_u8(b.to_ascii_lowercase());
        }
        state.write_u8(0xff);
    }
}

#[cfg(test)]
mod tests {
    use super::{FnvMap, NoCase};

    #[test]
    fn names_in_other_cases_are_one_key() {
        let mut m: FnvMap<NoCase, usize> = FnvMap::default();
        m.insert(NoCase("Speed"), 1);
        assert_eq!(m.get(&NoCase("SPEED")), Some(&1));
        assert_eq!(m.get(&NoCase("speed_2")), None);
    }
}
