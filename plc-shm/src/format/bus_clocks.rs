//! The distributed clocks of a bus, one type from the backend that reads them through the
//! status block to the tools that show them.

use std::fmt;

/// How well the distributed clocks of a bus with SYNC0 agree, and where the cycle falls
/// against SYNC0, as the last exchange saw them. A backend without distributed clocks reports
/// none ([`IoStatus::clocks`](crate::IoStatus::clocks) is `None`).
///
/// It shows as `plc list` prints it:
///
/// ```
/// use plc_shm::BusClocks;
/// let clocks = BusClocks {
///     sync0_period_ns: 1_000_000,
///     max_time_difference_ns: Some(3),
///     sync0_offset_ns: 120_000,
/// };
/// assert_eq!(
///     clocks.to_string(),
///     "sync0 1 ms, clocks within 3 ns, cycle 120 us after SYNC0"
/// );
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct BusClocks {
    /// The SYNC0 period configured (ns, never 0).
    pub sync0_period_ns: u32,
    /// The largest system time difference among the devices with distributed clocks
    /// (EtherCAT register 0x092C, magnitude, ns): below 100 ns on a settled bus. `None` before
    /// the first reading or when the last one got no answer.
    pub max_time_difference_ns: Option<u32>,
    /// When the last exchange's frame passed the reference clock, after the last SYNC0 pulse
    /// (ns): the cycle's phase against SYNC0. A value that wanders means the cycle's clock and
    /// the bus's time drift apart.
    pub sync0_offset_ns: u64,
}

/// The status word of a difference not read.
const NOT_READ: u64 = u64::MAX;

impl BusClocks {
    /// The three status words: SYNC0 period (0: no clocks), largest difference
    /// ([`NOT_READ`] when unknown), offset to SYNC0.
    pub(crate) fn to_words(clocks: Option<&BusClocks>) -> [u64; 3] {
        match clocks {
            None => [0, 0, 0],
            Some(c) => [
                u64::from(c.sync0_period_ns),
                c.max_time_difference_ns.map_or(NOT_READ, u64::from),
                c.sync0_offset_ns,
            ],
        }
    }

    /// The clocks the status words hold. The words come from another process: a period that
    /// is 0 or does not fit means none, a difference that does not fit means not read.
    pub(crate) fn from_words([period, difference, offset]: [u64; 3]) -> Option<BusClocks> {
        let sync0_period_ns = u32::try_from(period).ok().filter(|&p| p > 0)?;
        Some(BusClocks {
            sync0_period_ns,
            max_time_difference_ns: u32::try_from(difference).ok(),
            sync0_offset_ns: offset,
        })
    }
}

impl fmt::Display for BusClocks {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "sync0 {}, ", Span(u64::from(self.sync0_period_ns)))?;
        match self.max_time_difference_ns {
            Some(d) => write!(f, "clocks within {}", Span(u64::from(d)))?,
            None => f.write_str("clocks not read yet")?,
        }
        write!(f, ", cycle {} after SYNC0", Span(self.sync0_offset_ns))
    }
}

/// Nanoseconds in the largest unit that keeps a whole number before the point, with one
/// decimal when it is not whole: `3 ns`, `120 us`, `1.5 ms`.
struct Span(u64);

impl fmt::Display for Span {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let ns = self.0;
        let (unit, name) = match ns {
            0..1_000 => return write!(f, "{ns} ns"),
            1_000..1_000_000 => (1_000, "us"),
            1_000_000..1_000_000_000 => (1_000_000, "ms"),
            _ => (1_000_000_000, "s"),
        };
        let (whole, tenth) = (ns / unit, ns % unit * 10 / unit);
        if tenth == 0 {
            write!(f, "{whole} {name}")
        } else {
            write!(f, "{whole}.{tenth} {name}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_take_the_largest_whole_unit_with_one_decimal() {
        let shown = |ns| Span(ns).to_string();
        assert_eq!(shown(0), "0 ns");
        assert_eq!(shown(999), "999 ns");
        assert_eq!(shown(1_000), "1 us");
        assert_eq!(shown(120_500), "120.5 us");
        assert_eq!(shown(1_000_000), "1 ms");
        assert_eq!(shown(250_000_000), "250 ms");
        assert_eq!(shown(u64::MAX), "18446744073.7 s");
    }

    #[test]
    fn clocks_round_trip_through_the_status_words() {
        let c = BusClocks {
            sync0_period_ns: 2_000_000,
            max_time_difference_ns: Some(u32::MAX),
            sync0_offset_ns: u64::MAX,
        };
        assert_eq!(
            BusClocks::from_words(BusClocks::to_words(Some(&c))),
            Some(c)
        );
        let unread = BusClocks {
            max_time_difference_ns: None,
            ..c
        };
        assert_eq!(
            BusClocks::from_words(BusClocks::to_words(Some(&unread))),
            Some(unread)
        );
        assert_eq!(BusClocks::from_words(BusClocks::to_words(None)), None);
    }

    #[test]
    fn damaged_words_read_as_no_clocks_or_an_unread_difference() {
        assert_eq!(BusClocks::from_words([1 << 40, 5, 5]), None);
        assert_eq!(BusClocks::from_words([0, 5, 5]), None);
        let c = BusClocks::from_words([1_000, 1 << 40, 7]).unwrap();
        assert_eq!(c.max_time_difference_ns, None);
        assert_eq!(
            c.to_string(),
            "sync0 1 us, clocks not read yet, cycle 7 ns after SYNC0"
        );
    }
}
