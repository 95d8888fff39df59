//! The SDO information service of a simulated SubDevice's CoE server (ETG.1000.6 §5.6.3): a
//! MainDevice reads what the object dictionary holds (Get OD List, opcode 0x01/0x02), each
//! object's name and kind (Get Object Description, 0x03/0x04) and each entry's data type, bit
//! length, access and name (Get Entry Description, 0x05/0x06). An unknown object or entry is
//! answered with an SDO Info Error (0x07) and an SDO abort code.
//!
//! Frames (after the 6-byte mailbox header): CoE header u16 (service 8 in bits 12-15), the SDO
//! information header (opcode in bits 0-6 and "incomplete" in bit 7 of the first byte, a
//! reserved byte, the fragments still to come u16), then the service's data. A reply longer
//! than the input mailbox is cut into fragments, each with the data's next bytes, that the
//! device hands over one after the other as the MainDevice reads the mailbox (see
//! `device/mailbox.rs`).
//!
//! Names and types are kept beside the values ([`Dictionary::objects`],
//! [`Dictionary::entry_info`]); each model says where its names come from (`data/README.md`).

use super::{ABORT_NO_OBJECT, ABORT_NO_SUB_INDEX, Dictionary};

/// CoE service "SDO information" (bits 12-15 of the CoE header).
pub(crate) const SDO_INFORMATION: u16 = 8;

/// SDO information opcodes (ETG.1000.6 table 43).
const GET_OD_LIST_REQUEST: u8 = 0x01;
const GET_OD_LIST_RESPONSE: u8 = 0x02;
const GET_OBJECT_REQUEST: u8 = 0x03;
const GET_OBJECT_RESPONSE: u8 = 0x04;
const GET_ENTRY_REQUEST: u8 = 0x05;
const GET_ENTRY_RESPONSE: u8 = 0x06;
const INFO_ERROR: u8 = 0x07;

/// "Client/server command specifier not valid or unknown": an opcode or list type this server
/// does not know.
const ABORT_UNKNOWN_COMMAND: u32 = super::ABORT_UNKNOWN_COMMAND;

/// Object codes (ETG.1000.6 table 62).
pub(crate) const VAR: u8 = 7;
pub(crate) const ARRAY: u8 = 8;
pub(crate) const RECORD: u8 = 9;

/// Basic data types (DEFTYPE, ETG.1000.6 table 63) the models use.
pub(crate) mod deftype {
    /// BOOLEAN.
    pub(crate) const BOOLEAN: u16 = 0x0001;
    /// INTEGER8.
    pub(crate) const INTEGER8: u16 = 0x0002;
    /// INTEGER16.
    pub(crate) const INTEGER16: u16 = 0x0003;
    /// INTEGER32.
    pub(crate) const INTEGER32: u16 = 0x0004;
    /// UNSIGNED8.
    pub(crate) const UNSIGNED8: u16 = 0x0005;
    /// UNSIGNED16.
    pub(crate) const UNSIGNED16: u16 = 0x0006;
    /// UNSIGNED32.
    pub(crate) const UNSIGNED32: u16 = 0x0007;
    /// VISIBLE_STRING.
    pub(crate) const VISIBLE_STRING: u16 = 0x0009;
    /// PDO_MAPPING (the record type of 0x16xx/0x1Axx).
    pub(crate) const PDO_MAPPING: u16 = 0x0021;
    /// IDENTITY (the record type of 0x1018).
    pub(crate) const IDENTITY: u16 = 0x0023;
    /// BIT2.
    pub(crate) const BIT2: u16 = 0x0031;
    /// BIT3.
    pub(crate) const BIT3: u16 = 0x0032;
}

/// Entry access (ETG.1000.6 table 44, ObjAccess): readable in PRE-OP, SAFE-OP and OP.
pub(crate) const READ: u16 = 0x0007;
/// Readable and writable in every state.
pub(crate) const READ_WRITE: u16 = 0x003F;
/// Bit 6: the entry can be mapped into an RxPDO (outputs).
pub(crate) const RX_MAPPABLE: u16 = 0x0040;
/// Bit 7: the entry can be mapped into a TxPDO (inputs).
pub(crate) const TX_MAPPABLE: u16 = 0x0080;

/// What Get Object Description tells of one object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct ObjectInfo {
    pub(crate) index: u16,
    pub(crate) name: String,
    /// [`VAR`], [`ARRAY`] or [`RECORD`].
    pub(crate) code: u8,
    /// The data type of a VAR or of an ARRAY's elements; the record type of a RECORD.
    pub(crate) data_type: u16,
    pub(crate) max_sub: u8,
}

/// What Get Entry Description tells of one entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct EntryInfo {
    pub(crate) index: u16,
    pub(crate) sub: u8,
    pub(crate) name: String,
    pub(crate) data_type: u16,
    pub(crate) bits: u16,
    pub(crate) access: u16,
}

/// The names of sub-indexes 1-255 of a record or array whose entries have no names of their
/// own, as Beckhoff's dictionaries show them: "SubIndex 001" ... "SubIndex 255".
pub(crate) fn sub_names() -> Vec<String> {
    (1..=255).map(|i| format!("SubIndex {i:03}")).collect()
}

/// One entry of a described record or array: sub-index, name, data type, bits, access.
pub(crate) type EntrySpec<'a> = (u8, &'a str, u16, u16, u16);

impl Dictionary {
    /// Describes a VAR object: its name (also its sub-index 0's, as devices name the single
    /// entry of a VAR after the object), data type, bit length and access.
    pub(crate) fn describe_var(&mut self, index: u16, name: &str, ty: u16, bits: u16, access: u16) {
        self.describe_object(index, name, VAR, ty, 0);
        self.describe_entry(index, (0, name, ty, bits, access));
    }

    /// Describes a RECORD or ARRAY `index` of type `ty` with the entries `entries` (sub-index
    /// 0, "SubIndex 000" UNSIGNED8, is added before them, `access` as given for it).
    pub(crate) fn describe_record(
        &mut self,
        index: u16,
        name: &str,
        code: u8,
        ty: u16,
        sub0_access: u16,
        entries: &[EntrySpec<'_>],
    ) {
        let max_sub = entries.iter().map(|e| e.0).max().unwrap_or(0);
        self.describe_object(index, name, code, ty, max_sub);
        let sub0 = (0, "SubIndex 000", deftype::UNSIGNED8, 8, sub0_access);
        self.describe_entry(index, sub0);
        for &e in entries {
            self.describe_entry(index, e);
        }
    }

    fn describe_object(&mut self, index: u16, name: &str, code: u8, data_type: u16, max_sub: u8) {
        self.objects.retain(|o| o.index != index);
        self.entry_info.retain(|e| e.index != index);
        self.objects.push(ObjectInfo {
            index,
            name: name.to_owned(),
            code,
            data_type,
            max_sub,
        });
    }

    fn describe_entry(&mut self, index: u16, (sub, name, data_type, bits, access): EntrySpec) {
        self.entry_info.push(EntryInfo {
            index,
            sub,
            name: name.to_owned(),
            data_type,
            bits,
            access,
        });
    }

    /// The indexes of the objects the dictionary holds, in ascending order (a value or a
    /// description makes an object).
    fn indexes(&self) -> Vec<u16> {
        let mut all: Vec<u16> = (self.entries.iter().map(|e| e.index))
            .chain(self.texts.iter().map(|t| t.0))
            .chain(self.objects.iter().map(|o| o.index))
            .collect();
        all.sort_unstable();
        all.dedup();
        all
    }

    /// The indexes of the objects with an entry whose access has `bit`.
    fn mappable(&self, bit: u16) -> Vec<u16> {
        let mut all: Vec<u16> = (self.entry_info.iter())
            .filter(|e| e.access & bit != 0)
            .map(|e| e.index)
            .collect();
        all.sort_unstable();
        all.dedup();
        all
    }

    /// Answers an SDO information request (`request` starts at the CoE header) with the
    /// replies (each starting at the CoE header) that fit `room` bytes: one, or the fragments
    /// of a longer answer in order.
    pub(crate) fn serve_info(&self, request: &[u8], room: usize) -> Vec<Vec<u8>> {
        let (opcode, data) = match request {
            [_, _, op, _, _, _, data @ ..] => (op & 0x7F, data),
            _ => return error(ABORT_UNKNOWN_COMMAND),
        };
        let u16_at = |at: usize| {
            data.get(at..at + 2)
                .map(|b| u16::from_le_bytes([b[0], b[1]]))
        };
        let answer = match opcode {
            GET_OD_LIST_REQUEST => match u16_at(0) {
                Some(list) => self.od_list(list),
                None => Err(ABORT_UNKNOWN_COMMAND),
            },
            GET_OBJECT_REQUEST => match u16_at(0) {
                Some(index) => self.object_description(index),
                None => Err(ABORT_UNKNOWN_COMMAND),
            },
            GET_ENTRY_REQUEST => match (u16_at(0), data.get(2)) {
                (Some(index), Some(&sub)) => self.entry_description(index, sub),
                _ => Err(ABORT_UNKNOWN_COMMAND),
            },
            _ => Err(ABORT_UNKNOWN_COMMAND),
        };
        match answer {
            Ok((opcode, data)) => fragments(opcode, &data, room),
            Err(code) => error(code),
        }
    }

    /// Get OD List: list type 0 the five counts, 1 every object, 2 RxPDO- and 3 TxPDO-mappable
    /// ones; 4 (backup) and 5 (startup) are empty here. The data starts with the list type.
    fn od_list(&self, list: u16) -> Result<(u8, Vec<u8>), u32> {
        let indexes = match list {
            0 => {
                let counts = [
                    self.indexes().len(),
                    self.mappable(RX_MAPPABLE).len(),
                    self.mappable(TX_MAPPABLE).len(),
                    0,
                    0,
                ];
                counts.map(|n| n as u16).to_vec()
            }
            1 => self.indexes(),
            2 => self.mappable(RX_MAPPABLE),
            3 => self.mappable(TX_MAPPABLE),
            4 | 5 => Vec::new(),
            _ => return Err(ABORT_UNKNOWN_COMMAND),
        };
        let mut data = list.to_le_bytes().to_vec();
        data.extend(indexes.iter().flat_map(|i| i.to_le_bytes()));
        Ok((GET_OD_LIST_RESPONSE, data))
    }

    /// Get Object Description: index, data type, max sub-index, object code, name.
    fn object_description(&self, index: u16) -> Result<(u8, Vec<u8>), u32> {
        let o = (self.objects.iter().find(|o| o.index == index)).ok_or(ABORT_NO_OBJECT)?;
        let mut data = index.to_le_bytes().to_vec();
        data.extend_from_slice(&o.data_type.to_le_bytes());
        data.extend_from_slice(&[o.max_sub, o.code]);
        data.extend_from_slice(o.name.as_bytes());
        Ok((GET_OBJECT_RESPONSE, data))
    }

    /// Get Entry Description without the optional value info (unit, default, minimum,
    /// maximum: value info 0 in the reply whatever was asked): index, sub-index, value info,
    /// data type, bit length, access, name.
    fn entry_description(&self, index: u16, sub: u8) -> Result<(u8, Vec<u8>), u32> {
        let Some(e) = (self.entry_info.iter()).find(|e| (e.index, e.sub) == (index, sub)) else {
            let known = self.objects.iter().any(|o| o.index == index);
            return Err(if known {
                ABORT_NO_SUB_INDEX
            } else {
                ABORT_NO_OBJECT
            });
        };
        let mut data = index.to_le_bytes().to_vec();
        data.extend_from_slice(&[sub, 0]);
        data.extend_from_slice(&e.data_type.to_le_bytes());
        data.extend_from_slice(&e.bits.to_le_bytes());
        data.extend_from_slice(&e.access.to_le_bytes());
        data.extend_from_slice(e.name.as_bytes());
        Ok((GET_ENTRY_RESPONSE, data))
    }
}

/// The CoE and SDO information headers of a reply.
pub(crate) fn header(opcode: u8, incomplete: bool, fragments_left: u16) -> Vec<u8> {
    let mut r = (SDO_INFORMATION << 12).to_le_bytes().to_vec();
    r.push(opcode | u8::from(incomplete) << 7);
    r.push(0);
    r.extend_from_slice(&fragments_left.to_le_bytes());
    r
}

/// `data` under `opcode`, cut into replies of at most `room` bytes: every fragment but the
/// last is "incomplete", and each counts the fragments still to come.
fn fragments(opcode: u8, data: &[u8], room: usize) -> Vec<Vec<u8>> {
    let per = room.saturating_sub(header(0, false, 0).len()).max(1);
    let chunks: Vec<&[u8]> = if data.is_empty() {
        vec![&[]]
    } else {
        data.chunks(per).collect()
    };
    let n = chunks.len();
    chunks
        .into_iter()
        .enumerate()
        .map(|(i, chunk)| {
            let left = (n - 1 - i) as u16;
            let mut r = header(opcode, left > 0, left);
            r.extend_from_slice(chunk);
            r
        })
        .collect()
}

/// An SDO Info Error reply with abort `code`.
fn error(code: u32) -> Vec<Vec<u8>> {
    let mut r = header(INFO_ERROR, false, 0);
    r.extend_from_slice(&code.to_le_bytes());
    vec![r]
}

/// A reply with the headers of an entry description that says more fragments follow, for
/// [`crate::SdoInfoFault::EndlessFragments`]: `left` fragments still to come.
pub(crate) fn endless_fragment(left: u16) -> Vec<u8> {
    let mut r = header(GET_ENTRY_RESPONSE, true, left);
    r.extend_from_slice(&[0; 16]);
    r
}

/// An SDO Info Error reply, for [`crate::SdoInfoFault::Refused`].
pub(crate) fn refusal() -> Vec<u8> {
    error(ABORT_UNKNOWN_COMMAND).remove(0)
}

#[cfg(test)]
mod tests {
    use super::super::el3004;
    use super::*;

    fn request(opcode: u8, data: &[u8]) -> Vec<u8> {
        let mut r = header(opcode, false, 0);
        r.extend_from_slice(data);
        r
    }

    #[test]
    fn an_entry_description_gives_type_bits_access_and_name() {
        let d = el3004(2, 0x0BBC_3052, 0x0015_0000);
        let r = d.serve_info(&request(GET_ENTRY_REQUEST, &[0x00, 0x60, 0x11, 0x00]), 122);
        assert_eq!(r.len(), 1);
        let r = &r[0];
        assert_eq!(r[..6], [0x00, 0x80, 0x06, 0, 0, 0]);
        assert_eq!(
            r[6..10],
            [0x00, 0x60, 0x11, 0x00],
            "index, sub-index, value info"
        );
        assert_eq!(r[10..12], 0x0003u16.to_le_bytes(), "INTEGER16");
        assert_eq!(r[12..14], 16u16.to_le_bytes());
        assert_eq!(r[14..16], (READ | TX_MAPPABLE).to_le_bytes());
        assert_eq!(&r[16..], b"Value");
    }

    #[test]
    fn an_object_description_gives_its_name_and_code() {
        let d = el3004(2, 0x0BBC_3052, 0x0015_0000);
        let r = d.serve_info(&request(GET_OBJECT_REQUEST, &[0x10, 0x60]), 122);
        let r = &r[0];
        assert_eq!(r[2], GET_OBJECT_RESPONSE);
        assert_eq!(r[6..8], [0x10, 0x60]);
        assert_eq!((r[10], r[11]), (0x11, RECORD), "max sub-index, RECORD");
        assert_eq!(&r[12..], b"AI Inputs Ch.2");
    }

    #[test]
    fn unknown_objects_and_entries_are_answered_with_an_info_error() {
        let d = el3004(2, 0x0BBC_3052, 0x0015_0000);
        let r = &d.serve_info(&request(GET_ENTRY_REQUEST, &[0x00, 0x60, 0x04, 0]), 122)[0];
        assert_eq!(
            (r[2], &r[6..]),
            (INFO_ERROR, &0x0609_0011u32.to_le_bytes()[..])
        );
        let r = &d.serve_info(&request(GET_OBJECT_REQUEST, &[0x00, 0x20]), 122)[0];
        assert_eq!(&r[6..], &0x0602_0000u32.to_le_bytes());
        let r = &d.serve_info(&request(0x09, &[]), 122)[0];
        assert_eq!(
            (r[2], &r[6..]),
            (INFO_ERROR, &0x0504_0001u32.to_le_bytes()[..])
        );
    }

    #[test]
    fn a_long_answer_comes_in_fragments_that_count_down() {
        let d = el3004(2, 0x0BBC_3052, 0x0015_0000);
        let whole = &d.serve_info(&request(GET_OD_LIST_REQUEST, &[1, 0]), 1000)[0];
        assert_eq!(whole[6..8], [1, 0], "the list type first");
        let r = d.serve_info(&request(GET_OD_LIST_REQUEST, &[1, 0]), 16);
        assert!(r.len() > 2);
        for (i, f) in r.iter().enumerate() {
            let left = (r.len() - 1 - i) as u16;
            assert_eq!(f[2], GET_OD_LIST_RESPONSE | u8::from(left > 0) << 7);
            assert_eq!(f[4..6], left.to_le_bytes());
            assert!(f.len() <= 16);
        }
        let joined: Vec<u8> = r.iter().flat_map(|f| f[6..].to_vec()).collect();
        assert_eq!(joined, whole[6..]);
    }
}
