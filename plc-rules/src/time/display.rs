//! How a [`Time`] is written: as the IEC literal (`LTIME#1d2h`) that parses back to it.

use super::duration::Time;
use super::unit::UNITS;
use core::fmt;

impl fmt::Debug for Time {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl fmt::Display for Time {
    /// The IEC literal: `LTIME#`, a `-` if negative, then every non-zero part from days to
    /// nanoseconds without separators (`LTIME#1d2h`), or `LTIME#0s` for zero.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("LTIME#")?;
        if self.is_negative() {
            f.write_str("-")?;
        }
        // `unsigned_abs` holds |MIN| = 2^63, which `abs` cannot.
        let mut rest = self.as_nanos().unsigned_abs();
        if rest == 0 {
            return f.write_str("0s");
        }
        for unit in UNITS {
            let count = rest / unit.ns;
            rest %= unit.ns;
            if count != 0 {
                write!(f, "{count}{}", unit.symbol)?;
            }
        }
        Ok(())
    }
}
