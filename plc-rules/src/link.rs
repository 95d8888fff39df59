//! Hardware links: `ethercat.<device>.<entry>` (the JSON variable-list format's "hardware FQDN
//! link"). The entry is a path of one or more dotted identifiers, as the framework's motion
//! axes name theirs (`ethercat.motion.x.position`: device `motion`, entry `x.position`).
//!
//! ```
//! use plc_rules::link::Link;
//! let l = Link::parse("ethercat.impact67_0.digital_inputs").unwrap();
//! assert_eq!((l.device, l.entry), ("impact67_0", "digital_inputs"));
//! let axis = Link::parse("ethercat.motion.x.actual_velocity").unwrap();
//! assert_eq!((axis.device, axis.entry), ("motion", "x.actual_velocity"));
//! ```

use core::fmt;

/// The only bus plc-vars links to today.
pub const ETHERCAT: &str = "ethercat";

/// A parsed link, borrowing from the link text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Link<'a> {
    /// The SubDevice's name in the bus description, e.g. `impact67_0`.
    pub device: &'a str,
    /// The PDO entry's name in the bus description, e.g. `digital_inputs`, or a dotted path
    /// such as `x.position`.
    pub entry: &'a str,
}

/// Why a link is malformed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkError {
    /// The link does not start with `ethercat.`.
    UnknownBus,
    /// The link has fewer than three dot-separated parts.
    Shape,
    /// The device part is not an identifier.
    BadDevice,
    /// A part of the entry path is not an identifier.
    BadEntry,
}

impl fmt::Display for LinkError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            LinkError::UnknownBus => {
                "a link must start with `ethercat.`: write `ethercat.<device>.<entry>`"
            }
            LinkError::Shape => {
                "a link has at least three parts: write `ethercat.<device>.<entry>`"
            }
            LinkError::BadDevice => {
                "the device of a link must be an identifier (letters, digits, underscores; \
                 not starting with a digit), e.g. `ethercat.el1004_0.input1`"
            }
            LinkError::BadEntry => {
                "the entry of a link must be an identifier, or identifiers joined by dots \
                 (letters, digits, underscores; not starting with a digit), e.g. \
                 `ethercat.el1004_0.input1` or `ethercat.motion.x.position`"
            }
        })
    }
}

#[cfg(feature = "std")]
impl std::error::Error for LinkError {}

/// Whether `s` is an ASCII identifier: a letter or underscore, then letters, digits, underscores.
pub fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Whether `s` is an entry path: one or more identifiers joined by dots (`x.position`).
pub fn is_entry_path(s: &str) -> bool {
    s.split('.').all(is_identifier)
}

impl<'a> Link<'a> {
    /// Parses `ethercat.<device>.<entry>`, the entry one or more dotted identifiers.
    pub fn parse(text: &'a str) -> Result<Self, LinkError> {
        let mut parts = text.splitn(3, '.');
        let (bus, device, entry) = match (parts.next(), parts.next(), parts.next()) {
            (Some(b), Some(d), Some(e)) => (b, d, e),
            (Some(b), ..) if b != ETHERCAT => return Err(LinkError::UnknownBus),
            _ => return Err(LinkError::Shape),
        };
        if bus != ETHERCAT {
            return Err(LinkError::UnknownBus);
        }
        if !is_identifier(device) {
            return Err(LinkError::BadDevice);
        }
        if !is_entry_path(entry) {
            return Err(LinkError::BadEntry);
        }
        Ok(Link { device, entry })
    }
}

impl fmt::Display for Link<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{ETHERCAT}.{}.{}", self.device, self.entry)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_format_links_parse() {
        for l in [
            "ethercat.el2004.output1",
            "ethercat.impact67_0.digital_outputs",
            "ethercat.motion.x.position",
            "ethercat.motion.x.actual_velocity",
            "ethercat.rack.slot1.ch2.value",
        ] {
            assert_eq!(Link::parse(l).unwrap().to_string(), l);
        }
    }

    #[test]
    fn malformed_links_say_what_is_wrong() {
        assert_eq!(Link::parse("modbus.a.b"), Err(LinkError::UnknownBus));
        assert_eq!(Link::parse("ethercat.a"), Err(LinkError::Shape));
        assert_eq!(Link::parse("ethercat.a.b..c"), Err(LinkError::BadEntry));
        assert_eq!(Link::parse("ethercat.a.b."), Err(LinkError::BadEntry));
        assert_eq!(Link::parse("ethercat.a.x.1st"), Err(LinkError::BadEntry));
        assert_eq!(Link::parse("ethercat.1a.b"), Err(LinkError::BadDevice));
        assert_eq!(Link::parse("ethercat.a.b-c"), Err(LinkError::BadEntry));
        assert_eq!(Link::parse("ethercat..b"), Err(LinkError::BadDevice));
        assert_eq!(Link::parse(""), Err(LinkError::UnknownBus));
    }
}
