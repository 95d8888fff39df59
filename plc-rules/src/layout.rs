//! The layout hash: FNV-1a 64 over the format version and, per variable, everything that fixes
//! where its bytes are. A reader compares it with the hash its own build computed, so it never
//! reads a segment through stale offsets.
//!
//! Per variable, in declaration order: name, 0, IEC name, 0, offset (u32 LE), size (u32 LE), the
//! count of dimensions (u32 LE), each dimension (u32 LE), the bit source index (u32 LE, `u32::MAX`
//! if none) and the bit (u8, `0xFF` if none).
//!
//! ```
//! use plc_rules::layout::LayoutHasher;
//! let h = LayoutHasher::new().var("speed", "DINT", 0, 4, &[], None).finish();
//! assert_ne!(h, LayoutHasher::new().finish());
//! ```

/// Version of the segment and descriptor format; part of every layout hash.
///
/// 2: mailbox slots carry a checksum over ticket and payload, and the owner's outcome (a tool
/// of format 1 would have its writes discarded by a format 2 owner, so it is refused at attach).
///
/// 3: the bus's distributed clocks in three words between the table of forces and the
/// descriptor (a tool of format 2 would look for the descriptor where the clocks are).
///
/// 4: the alarm counts (active, unacknowledged) in two words between the clocks and the
/// descriptor (a tool of format 3 would look for the descriptor where the counts are).
///
/// 5: the descriptor lists the alarms, and a table of their states follows it (a tool of
/// format 4 would show no alarm, and count on a segment that ends at the descriptor).
pub const FORMAT_VERSION: u32 = 5;

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

/// A `const` FNV-1a 64 hasher that the derive uses at compile time and tools use at run time.
#[derive(Clone, Copy, Debug)]
pub struct LayoutHasher(u64);

impl LayoutHasher {
    /// Starts a hash with [`FORMAT_VERSION`] already fed.
    pub const fn new() -> Self {
        LayoutHasher(FNV_OFFSET).u32(FORMAT_VERSION)
    }

    /// Feeds raw bytes.
    pub const fn bytes(mut self, bytes: &[u8]) -> Self {
        let mut i = 0;
        while i < bytes.len() {
            self.0 ^= bytes[i] as u64;
            self.0 = self.0.wrapping_mul(FNV_PRIME);
            i += 1;
        }
        self
    }

    /// Feeds a `u32` in little-endian order.
    pub const fn u32(self, v: u32) -> Self {
        self.bytes(&v.to_le_bytes())
    }

    /// Feeds one variable as the module documentation describes.
    pub const fn var(
        self,
        name: &str,
        iec_name: &str,
        offset: usize,
        size: usize,
        dims: &[usize],
        bit: Option<(usize, u8)>,
    ) -> Self {
        let mut h = self
            .bytes(name.as_bytes())
            .bytes(&[0])
            .bytes(iec_name.as_bytes())
            .bytes(&[0])
            .u32(offset as u32)
            .u32(size as u32)
            .u32(dims.len() as u32);
        let mut i = 0;
        while i < dims.len() {
            h = h.u32(dims[i] as u32);
            i += 1;
        }
        match bit {
            Some((source, bit)) => h.u32(source as u32).bytes(&[bit]),
            None => h.u32(u32::MAX).bytes(&[0xFF]),
        }
    }

    /// The hash value.
    pub const fn finish(self) -> u64 {
        self.0
    }
}

impl Default for LayoutHasher {
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_of_known_bytes_matches_the_reference_value() {
        // FNV-1a 64 of "a" is 0xaf63dc4c8601ec8c (reference value of the algorithm).
        assert_eq!(
            LayoutHasher(FNV_OFFSET).bytes(b"a").finish(),
            0xaf63_dc4c_8601_ec8c
        );
    }

    #[test]
    fn every_field_of_a_variable_changes_the_hash() {
        let base = LayoutHasher::new()
            .var("a", "INT", 0, 2, &[], None)
            .finish();
        let variants = [
            LayoutHasher::new()
                .var("b", "INT", 0, 2, &[], None)
                .finish(),
            LayoutHasher::new()
                .var("a", "UINT", 0, 2, &[], None)
                .finish(),
            LayoutHasher::new()
                .var("a", "INT", 1, 2, &[], None)
                .finish(),
            LayoutHasher::new()
                .var("a", "INT", 0, 4, &[], None)
                .finish(),
            LayoutHasher::new()
                .var("a", "INT", 0, 2, &[1], None)
                .finish(),
            LayoutHasher::new()
                .var("a", "INT", 0, 2, &[], Some((0, 0)))
                .finish(),
        ];
        for v in variants {
            assert_ne!(v, base);
        }
    }
}
