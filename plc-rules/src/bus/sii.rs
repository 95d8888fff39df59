//! The SubDevice Information (SII) an EtherCAT SubDevice keeps in its EEPROM, as ETG.2010
//! lays it out: the identity and mailbox words of the header, then categories from word 0x40
//! (strings, General, SyncManager, TxPDO, RxPDO, ...), each a type word, a length word (in
//! words) and its data, until a type 0xFFFF.
//!
//! The bytes come from a device, so nothing in them is trusted: every length is checked
//! against the bytes there are, every loop is bounded by the input, nothing is allocated by
//! a count the device gave beyond what its bytes hold, and bad data is an [`SiiError`] naming
//! the category, never a panic.
//!
//! ```
//! use plc_rules::bus::sii::{Sii, CATEGORIES_START};
//! // Header (identity at word 8), then a strings category, a General category and the end.
//! let mut image = vec![0u8; CATEGORIES_START];
//! image[0x10..0x1C].copy_from_slice(&[2, 0, 0, 0, 0x52, 0x30, 0xec, 0x03, 0, 0, 0x13, 0]);
//! image.extend_from_slice(&[10, 0, 4, 0, 1, 6]);
//! image.extend_from_slice(b"EL1004");
//! image.extend_from_slice(&[30, 0, 2, 0, 0, 0, 1, 0]);
//! image.extend_from_slice(&[0xff, 0xff, 0, 0]);
//! let sii = Sii::parse(&image).unwrap();
//! assert_eq!(sii.product, 0x03ec_3052);
//! assert_eq!(sii.order_name(), Some("EL1004"));
//! ```

use std::fmt;

/// Byte offset of the first category (word 0x40).
pub const CATEGORIES_START: usize = 0x80;

/// Most categories read before giving up on a chain that never ends (a real EEPROM has about
/// ten).
pub const MAX_CATEGORIES: usize = 256;

/// Mailbox protocol bit of CoE in header word 0x1C.
const MAILBOX_COE: u16 = 0x0004;

/// Category types (ETG.2010 table 3).
pub mod category {
    /// Strings, referenced by 1-based index from the other categories.
    pub const STRINGS: u16 = 10;
    /// General information: group, order number and name string indexes, CoE details.
    pub const GENERAL: u16 = 30;
    /// FMMU usage.
    pub const FMMU: u16 = 40;
    /// SyncManagers, 8 bytes each.
    pub const SYNC_MANAGER: u16 = 41;
    /// TxPDOs (inputs of the MainDevice).
    pub const TX_PDO: u16 = 50;
    /// RxPDOs (outputs of the MainDevice).
    pub const RX_PDO: u16 = 51;
    /// The end of the chain.
    pub const END: u16 = 0xFFFF;
}

/// A category's header: its type and its length in bytes (two words before its data).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CategoryHeader {
    /// The type ([`category`]); [`category::END`] ends the chain.
    pub kind: u16,
    /// Bytes of data after the header.
    pub len: usize,
}

impl CategoryHeader {
    /// Bytes of a category header.
    pub const SIZE: usize = 4;

    /// The header in `bytes` (type word, length word), as the EEPROM holds it.
    pub fn from_bytes(bytes: [u8; 4]) -> Self {
        CategoryHeader {
            kind: u16::from_le_bytes([bytes[0], bytes[1]]),
            len: 2 * u16::from_le_bytes([bytes[2], bytes[3]]) as usize,
        }
    }

    /// Whether this header ends the chain.
    pub fn is_end(&self) -> bool {
        self.kind == category::END
    }
}

/// What a SyncManager is used for (its type byte in the SyncManager category).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SmUsage {
    /// Not used (type 0).
    Unused,
    /// Mailbox from the MainDevice (1).
    MailboxOut,
    /// Mailbox to the MainDevice (2).
    MailboxIn,
    /// Process data outputs (3).
    Outputs,
    /// Process data inputs (4).
    Inputs,
    /// Another type byte.
    Other(u8),
}

impl SmUsage {
    fn from_byte(b: u8) -> Self {
        match b {
            0 => SmUsage::Unused,
            1 => SmUsage::MailboxOut,
            2 => SmUsage::MailboxIn,
            3 => SmUsage::Outputs,
            4 => SmUsage::Inputs,
            other => SmUsage::Other(other),
        }
    }
}

/// One SyncManager of the SyncManager category.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SyncManager {
    /// Physical start address in the ESC.
    pub start: u16,
    /// Length in bytes (0 where the MainDevice sizes it from the PDOs).
    pub len: u16,
    /// Control byte.
    pub control: u8,
    /// Enable byte.
    pub enable: u8,
    /// What it is used for.
    pub usage: SmUsage,
}

/// One PDO entry of a TxPDO or RxPDO category.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SiiPdoEntry {
    /// Object index (0 for a gap).
    pub index: u16,
    /// Sub-index.
    pub subindex: u8,
    /// 1-based index of its name in the strings category (0: no name).
    pub name: u8,
    /// CoE data type (ETG.1000.6 table 63: 1 BOOLEAN, 3 INTEGER16, 6 UNSIGNED16, ...).
    pub data_type: u8,
    /// Bits in the process data.
    pub bits: u8,
}

/// One PDO of a TxPDO or RxPDO category.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SiiPdo {
    /// PDO index (0x1Axx for a TxPDO, 0x16xx for an RxPDO).
    pub index: u16,
    /// The SyncManager it is assigned to by default.
    pub sm: u8,
    /// 1-based index of its name in the strings category (0: no name).
    pub name: u8,
    /// Its entries, in order.
    pub entries: Vec<SiiPdoEntry>,
}

/// The parsed SII of one SubDevice.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sii {
    /// Vendor id (word 0x08).
    pub vendor: u32,
    /// Product code (word 0x0A).
    pub product: u32,
    /// Revision (word 0x0C).
    pub revision: u32,
    /// Mailbox protocols (word 0x1C: bit 2 CoE).
    pub mailbox_protocols: u16,
    /// The strings, index 1 first; bytes outside printable ASCII read as `?`.
    pub strings: Vec<String>,
    /// General category: (group, image, order number, name) string indexes, if present.
    pub general: Option<[u8; 4]>,
    /// The SyncManager category, in index order.
    pub sync_managers: Vec<SyncManager>,
    /// The TxPDO category (inputs).
    pub tx_pdos: Vec<SiiPdo>,
    /// The RxPDO category (outputs).
    pub rx_pdos: Vec<SiiPdo>,
}

/// Why SII bytes could not be parsed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SiiError {
    /// Fewer bytes than the header (words 0x00-0x3F).
    ShortHeader(usize),
    /// A category's length runs past the bytes read.
    Truncated {
        /// Its type.
        kind: u16,
        /// Its byte offset.
        at: usize,
    },
    /// Bytes inside a category do not parse.
    Malformed {
        /// Its type.
        kind: u16,
        /// What is wrong.
        problem: String,
    },
    /// No end marker within [`MAX_CATEGORIES`] categories.
    Endless,
}

impl fmt::Display for SiiError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SiiError::ShortHeader(n) => write!(
                f,
                "the EEPROM gave {n} bytes, fewer than its {CATEGORIES_START}-byte header"
            ),
            SiiError::Truncated { kind, at } => write!(
                f,
                "EEPROM category {kind} at byte {at:#x} runs past the end of the EEPROM"
            ),
            SiiError::Malformed { kind, problem } => {
                write!(f, "EEPROM category {kind}: {problem}")
            }
            SiiError::Endless => write!(
                f,
                "the EEPROM's category list has no end within {MAX_CATEGORIES} categories"
            ),
        }
    }
}

impl std::error::Error for SiiError {}

fn u16_at(b: &[u8], at: usize) -> u16 {
    u16::from_le_bytes([b[at], b[at + 1]])
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
}

impl Sii {
    /// Parses an EEPROM image from word 0: the header and every category up to the end
    /// marker (or the end of `image`, for an image read without one). Unknown categories are
    /// skipped.
    pub fn parse(image: &[u8]) -> Result<Sii, SiiError> {
        if image.len() < CATEGORIES_START {
            return Err(SiiError::ShortHeader(image.len()));
        }
        let mut sii = Sii {
            vendor: u32_at(image, 0x10),
            product: u32_at(image, 0x14),
            revision: u32_at(image, 0x18),
            mailbox_protocols: u16_at(image, 0x38),
            ..Sii::default()
        };
        let mut at = CATEGORIES_START;
        for _ in 0..MAX_CATEGORIES {
            let Some(&[a, b, c, d]) = image.get(at..at + CategoryHeader::SIZE) else {
                return Ok(sii);
            };
            let header = CategoryHeader::from_bytes([a, b, c, d]);
            if header.is_end() {
                return Ok(sii);
            }
            let start = at + CategoryHeader::SIZE;
            let data = image
                .get(start..start + header.len)
                .ok_or(SiiError::Truncated {
                    kind: header.kind,
                    at,
                })?;
            sii.read_category(header.kind, data)?;
            at = start + header.len;
        }
        Err(SiiError::Endless)
    }

    fn read_category(&mut self, kind: u16, data: &[u8]) -> Result<(), SiiError> {
        let malformed = |problem: String| SiiError::Malformed { kind, problem };
        match kind {
            category::STRINGS if self.strings.is_empty() => {
                self.strings = strings(data).map_err(malformed)?;
            }
            category::GENERAL if self.general.is_none() => {
                let g = data
                    .get(..4)
                    .ok_or_else(|| malformed(format!("{} bytes, fewer than 4", data.len())))?;
                self.general = Some([g[0], g[1], g[2], g[3]]);
            }
            category::SYNC_MANAGER if self.sync_managers.is_empty() => {
                self.sync_managers = data
                    .chunks_exact(8)
                    .map(|c| SyncManager {
                        start: u16_at(c, 0),
                        len: u16_at(c, 2),
                        control: c[4],
                        enable: c[6],
                        usage: SmUsage::from_byte(c[7]),
                    })
                    .collect();
            }
            category::TX_PDO => self.tx_pdos.extend(pdos(data).map_err(malformed)?),
            category::RX_PDO => self.rx_pdos.extend(pdos(data).map_err(malformed)?),
            _ => {}
        }
        Ok(())
    }

    /// The string at 1-based `index` (0, or one past the list: `None`).
    pub fn string(&self, index: u8) -> Option<&str> {
        let i = usize::from(index).checked_sub(1)?;
        self.strings.get(i).map(String::as_str)
    }

    /// The order number (General category), e.g. `"EL1004"`: the name ethercrab gives the
    /// SubDevice.
    pub fn order_name(&self) -> Option<&str> {
        self.string(self.general?[2])
    }

    /// The device's long name (General category), e.g. `"EL1004 4K. Dig. Eingang 24V, 3ms"`.
    pub fn device_name(&self) -> Option<&str> {
        self.string(self.general?[3])
    }

    /// Whether the mailbox speaks CoE (header word 0x1C).
    pub fn has_coe(&self) -> bool {
        self.mailbox_protocols & MAILBOX_COE != 0
    }
}

/// The strings category: a count, then each string as a length byte and its bytes.
fn strings(data: &[u8]) -> Result<Vec<String>, String> {
    let Some((&count, mut rest)) = data.split_first() else {
        return Ok(Vec::new());
    };
    let mut out = Vec::with_capacity(usize::from(count));
    for i in 1..=count {
        let (&len, tail) = rest
            .split_first()
            .ok_or_else(|| format!("string {i} of {count} is missing"))?;
        let text = tail
            .get(..usize::from(len))
            .ok_or_else(|| format!("string {i} ({len} bytes) runs past the category"))?;
        out.push(
            text.iter()
                .map(|&b| {
                    if b.is_ascii_graphic() || b == b' ' {
                        b as char
                    } else {
                        '?'
                    }
                })
                .collect(),
        );
        rest = &tail[usize::from(len)..];
    }
    Ok(out)
}

/// A TxPDO or RxPDO category: PDOs of an 8-byte header and 8-byte entries each.
fn pdos(data: &[u8]) -> Result<Vec<SiiPdo>, String> {
    let mut out = Vec::new();
    let mut rest = data;
    // Each PDO takes at least its 8-byte header, so this loop ends within data.len() / 8.
    while let Some(header) = rest.get(..8) {
        let pdo_index = u16_at(header, 0);
        let count = usize::from(header[2]);
        let body = rest.get(8..8 + 8 * count).ok_or_else(|| {
            format!("PDO {pdo_index:#06x}: its {count} entries run past the category")
        })?;
        let entries = body
            .chunks_exact(8)
            .map(|e| SiiPdoEntry {
                index: u16_at(e, 0),
                subindex: e[2],
                name: e[3],
                data_type: e[4],
                bits: e[5],
            })
            .collect();
        out.push(SiiPdo {
            index: pdo_index,
            sm: header[3],
            name: header[5],
            entries,
        });
        rest = &rest[8 + 8 * count..];
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A header with `identity` and the CoE bit as asked, followed by `categories`.
    fn image(coe: bool, categories: &[(u16, Vec<u8>)]) -> Vec<u8> {
        let mut b = vec![0u8; CATEGORIES_START];
        b[0x10..0x14].copy_from_slice(&2u32.to_le_bytes());
        b[0x14..0x18].copy_from_slice(&0x0b49_3052u32.to_le_bytes());
        b[0x18..0x1C].copy_from_slice(&0x0011_0000u32.to_le_bytes());
        if coe {
            b[0x38] = 0x04;
        }
        for (kind, data) in categories {
            let mut data = data.clone();
            if data.len() % 2 == 1 {
                data.push(0);
            }
            b.extend_from_slice(&kind.to_le_bytes());
            b.extend_from_slice(&(data.len() as u16 / 2).to_le_bytes());
            b.extend_from_slice(&data);
        }
        b.extend_from_slice(&[0xff, 0xff, 0, 0]);
        b
    }

    fn strings_category(list: &[&str]) -> Vec<u8> {
        let mut d = vec![list.len() as u8];
        for s in list {
            d.push(s.len() as u8);
            d.extend_from_slice(s.as_bytes());
        }
        d
    }

    #[test]
    fn identity_strings_general_sync_managers_and_pdos_are_read() {
        let pdo = [
            0x00, 0x16, 2, 1, 0, 2, 0x11, 0, // 0x1600, 2 entries, SM1, name 2
            0x00, 0x70, 1, 3, 1, 1, 0, 0, // 0x7000:01 "Output" BOOL 1 bit
            0x00, 0x00, 0, 0, 0, 7, 0, 0, // a 7-bit gap
        ];
        let sm = [0x00, 0x0f, 1, 0, 0x44, 0, 0x09, 3];
        let b = image(
            true,
            &[
                (
                    category::STRINGS,
                    strings_category(&["EL2889", "Ch 1", "Output"]),
                ),
                (category::GENERAL, vec![0, 0, 1, 2, 0, 0]),
                (category::SYNC_MANAGER, sm.to_vec()),
                (category::RX_PDO, pdo.to_vec()),
            ],
        );
        let sii = Sii::parse(&b).unwrap();
        assert_eq!(
            (sii.vendor, sii.product, sii.revision),
            (2, 0x0b49_3052, 0x0011_0000)
        );
        assert!(sii.has_coe());
        assert_eq!(sii.order_name(), Some("EL2889"));
        assert_eq!(sii.device_name(), Some("Ch 1"));
        assert_eq!(sii.string(0), None);
        assert_eq!(sii.string(4), None);
        assert_eq!(sii.sync_managers[0].usage, SmUsage::Outputs);
        assert_eq!(sii.sync_managers[0].start, 0x0f00);
        let p = &sii.rx_pdos[0];
        assert_eq!((p.index, p.sm, p.name), (0x1600, 1, 2));
        assert_eq!(p.entries[0].index, 0x7000);
        assert_eq!(sii.string(p.entries[0].name), Some("Output"));
        assert_eq!((p.entries[1].index, p.entries[1].bits), (0, 7));
        assert!(sii.tx_pdos.is_empty());
    }

    #[test]
    fn non_ascii_bytes_in_a_string_read_as_question_marks() {
        let mut s = strings_category(&["ab"]);
        s.extend_from_slice(&[4, b'x', 0xe9, 0, b'\n']);
        s[0] = 2;
        let sii = Sii::parse(&image(false, &[(category::STRINGS, s)])).unwrap();
        assert_eq!(sii.strings, ["ab", "x???"]);
    }

    #[test]
    fn a_category_longer_than_the_image_is_an_error_naming_it() {
        let mut b = image(false, &[]);
        let end = b.len() - 4;
        b[end..end + 4].copy_from_slice(&[50, 0, 0x10, 0]);
        assert_eq!(
            Sii::parse(&b),
            Err(SiiError::Truncated {
                kind: 50,
                at: CATEGORIES_START
            })
        );
    }

    #[test]
    fn pdo_entries_beyond_the_category_are_an_error() {
        let pdo = vec![0x00, 0x1a, 3, 0, 0, 0, 0, 0, 0x00, 0x60, 1, 0, 1, 1, 0, 0];
        let err = Sii::parse(&image(false, &[(category::TX_PDO, pdo)])).unwrap_err();
        assert!(
            err.to_string().contains("PDO 0x1a00: its 3 entries"),
            "{err}"
        );
    }

    #[test]
    fn a_string_list_shorter_than_its_count_is_an_error() {
        let mut s = strings_category(&["one"]);
        s[0] = 3;
        let err = Sii::parse(&image(false, &[(category::STRINGS, s)])).unwrap_err();
        // The category's padding byte (0) reads as an empty string 2.
        assert_eq!(
            err.to_string(),
            "EEPROM category 10: string 3 of 3 is missing"
        );
    }

    #[test]
    fn an_image_without_an_end_marker_ends_at_its_last_category() {
        let mut b = image(false, &[(category::GENERAL, vec![0, 0, 1, 0])]);
        b.truncate(b.len() - 4);
        assert_eq!(Sii::parse(&b).unwrap().general, Some([0, 0, 1, 0]));
        assert_eq!(Sii::parse(&b[..0x20]), Err(SiiError::ShortHeader(0x20)));
    }

    #[test]
    fn a_chain_of_empty_categories_without_end_is_refused() {
        let mut b = vec![0u8; CATEGORIES_START];
        for _ in 0..MAX_CATEGORIES + 1 {
            b.extend_from_slice(&[1, 0, 0, 0]);
        }
        assert_eq!(Sii::parse(&b), Err(SiiError::Endless));
    }

    proptest! {
        #[test]
        fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..600)) {
            let _ = Sii::parse(&bytes);
        }

        #[test]
        fn arbitrary_categories_after_a_header_never_panic(
            tail in proptest::collection::vec(any::<u8>(), 0..600),
            kinds in proptest::collection::vec(prop_oneof![Just(10u16), Just(30), Just(41), Just(50), Just(51)], 1..4),
        ) {
            // Real category types with random lengths and bodies reach every parser.
            let mut b = vec![0u8; CATEGORIES_START];
            let mut rest = tail.as_slice();
            for kind in kinds {
                let take = rest.len().min(usize::from(rest.first().copied().unwrap_or(0)));
                b.extend_from_slice(&kind.to_le_bytes());
                b.extend_from_slice(&((take as u16).div_ceil(2)).to_le_bytes());
                b.extend_from_slice(&rest[..take]);
                rest = &rest[take..];
            }
            let _ = Sii::parse(&b);
        }
    }
}
