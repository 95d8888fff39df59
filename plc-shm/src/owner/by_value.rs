//! Maps and sets keyed by a basic value's (variable, leaf), as the force table looks them up
//! several times per forced value.

use std::collections::{HashMap, HashSet};
use std::hash::{BuildHasherDefault, Hasher};

/// A map by value (variable, leaf).
pub(crate) type ByValue<V> = HashMap<(usize, usize), V, BuildHasherDefault<IndexHasher>>;

/// A set of values (variable, leaf).
pub(crate) type ValueSet = HashSet<(usize, usize), BuildHasherDefault<IndexHasher>>;

/// Hashes a value's (variable, leaf) with a rotate and a multiply per number (as rustc's
/// FxHash does). The keys are checked against the declaration and at most
/// [`MAX_FORCES`](crate::limits::MAX_FORCES) are held, so a tool that chose colliding keys makes a lookup a search of at
/// most that many; SipHash's defence against such keys would cost every lookup of every
/// force request.
#[derive(Default)]
pub(crate) struct IndexHasher(u64);

impl Hasher for IndexHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_usize(&mut self, n: usize) {
        self.write_u64(n as u64);
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::limits::MAX_FORCES;

    #[test]
    fn every_value_of_a_large_declaration_is_found_and_nothing_else() {
        let mut map = ByValue::default();
        for index in 0..MAX_FORCES {
            map.insert((index, index % 7), index);
        }
        for index in 0..MAX_FORCES {
            assert_eq!(map.get(&(index, index % 7)), Some(&index));
            assert_eq!(map.get(&(index, index % 7 + 1)), None);
        }
    }
}
