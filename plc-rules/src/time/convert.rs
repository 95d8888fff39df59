//! A [`Time`] from a [`Duration`](core::time::Duration), and as its literal in serde.

use super::duration::Time;
use super::error::TimeError;
#[cfg(feature = "serde")]
use core::fmt;

impl TryFrom<core::time::Duration> for Time {
    type Error = TimeError;

    /// A [`Duration`](core::time::Duration) as an `LTIME`: an error beyond [`Time::MAX`].
    fn try_from(d: core::time::Duration) -> Result<Self, Self::Error> {
        i64::try_from(d.as_nanos())
            .map(Time::from_nanos)
            .map_err(|_| TimeError::Overflow)
    }
}

/// Serialized as its IEC literal (`"LTIME#1s500ms"`); read back from any literal the grammar
/// accepts.
#[cfg(feature = "serde")]
impl serde::Serialize for Time {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for Time {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl serde::de::Visitor<'_> for Visitor {
            type Value = Time;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an IEC duration literal such as \"T#1s500ms\"")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Time, E> {
                Time::parse(v).map_err(E::custom)
            }
        }
        deserializer.deserialize_str(Visitor)
    }
}
