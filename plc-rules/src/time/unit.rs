//! The units of the duration grammar, largest first, and their lengths in nanoseconds: what
//! the parser reads and the display writes.

pub(super) const NS_PER_US: i64 = 1_000;
pub(super) const NS_PER_MS: i64 = 1_000_000;
pub(super) const NS_PER_S: i64 = 1_000_000_000;

/// A unit of the grammar: its symbol, its length in nanoseconds, and the value a later part
/// of it must stay below (the next larger unit; none for days).
pub(super) struct Unit {
    pub(super) symbol: &'static str,
    pub(super) ns: u64,
    pub(super) limit: u64,
}

/// The units, largest first: the order the parts must come in.
pub(super) const UNITS: [Unit; 7] = [
    Unit {
        symbol: "d",
        ns: 86_400 * NS_PER_S as u64,
        limit: u64::MAX,
    },
    Unit {
        symbol: "h",
        ns: 3_600 * NS_PER_S as u64,
        limit: 24,
    },
    Unit {
        symbol: "m",
        ns: 60 * NS_PER_S as u64,
        limit: 60,
    },
    Unit {
        symbol: "s",
        ns: NS_PER_S as u64,
        limit: 60,
    },
    Unit {
        symbol: "ms",
        ns: NS_PER_MS as u64,
        limit: 1000,
    },
    Unit {
        symbol: "us",
        ns: NS_PER_US as u64,
        limit: 1000,
    },
    Unit {
        symbol: "ns",
        ns: 1,
        limit: 1000,
    },
];
