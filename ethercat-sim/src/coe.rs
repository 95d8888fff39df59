//! CoE (CANopen over EtherCAT) SDO server of a simulated SubDevice: an object dictionary and
//! the expedited upload/download services ethercrab uses (EMULATOR-NOTES §8), plus the normal
//! upload of objects longer than 4 bytes (strings such as the device name) that fit one
//! mailbox. Segmented transfers are not simulated.
//!
//! Frames (after the 6-byte mailbox header): CoE header u16 (service in bits 12-15: 2 SDO
//! request, 3 SDO response), SDO command byte, index u16, sub-index u8, 4 data bytes; a normal
//! upload response has the complete size in those 4 bytes and the data after them.
//!
//! The SDO information service (object and entry names, data types) is in [`info`].

mod info;

pub(crate) use info::{
    ARRAY, READ, READ_WRITE, RECORD, RX_MAPPABLE, TX_MAPPABLE, deftype, sub_names,
};
pub(crate) use info::{SDO_INFORMATION, endless_fragment, refusal};

/// CoE services (bits 12-15 of the CoE header).
const SDO_REQUEST: u16 = 2;
const SDO_RESPONSE: u16 = 3;

/// SDO abort codes (ETG.1000.6 table 41).
const ABORT_UNKNOWN_COMMAND: u32 = 0x0504_0001;
const ABORT_READ_ONLY: u32 = 0x0601_0002;
const ABORT_NO_OBJECT: u32 = 0x0602_0000;
const ABORT_NO_SUB_INDEX: u32 = 0x0609_0011;
/// "General error": the reply a segmented upload would need, which is not simulated.
const ABORT_NOT_SIMULATED: u32 = 0x0800_0000;

/// One object entry: its value and size in bytes (1, 2 or 4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Entry {
    pub(crate) index: u16,
    pub(crate) sub: u8,
    pub(crate) value: u32,
    pub(crate) size: u8,
    pub(crate) writable: bool,
}

/// An object dictionary: entries by index and sub-index, and read-only byte strings; and
/// what the SDO information service tells of them (names, object codes, data types).
#[derive(Clone, Debug, Default)]
pub(crate) struct Dictionary {
    pub(crate) entries: Vec<Entry>,
    /// Objects longer than 4 bytes (VISIBLE STRING), uploaded the normal way.
    pub(crate) texts: Vec<(u16, u8, Vec<u8>)>,
    /// Object descriptions (Get Object Description).
    pub(crate) objects: Vec<info::ObjectInfo>,
    /// Entry descriptions (Get Entry Description).
    pub(crate) entry_info: Vec<info::EntryInfo>,
}

impl Dictionary {
    /// Adds (or replaces) an entry.
    pub(crate) fn set(&mut self, index: u16, sub: u8, value: u32, size: u8, writable: bool) {
        self.entries.retain(|e| (e.index, e.sub) != (index, sub));
        self.entries.push(Entry {
            index,
            sub,
            value,
            size,
            writable,
        });
    }

    /// Adds a record: sub 0 = number of entries (u8), then `items` of `size` bytes each.
    pub(crate) fn record(&mut self, index: u16, items: &[u32], size: u8, writable: bool) {
        self.set(index, 0, items.len() as u32, 1, writable);
        for (i, &v) in items.iter().enumerate() {
            self.set(index, i as u8 + 1, v, size, writable);
        }
    }

    /// Adds a read-only string object (sub-index 0).
    pub(crate) fn text(&mut self, index: u16, text: &str) {
        self.texts.retain(|t| t.0 != index);
        self.texts.push((index, 0, text.as_bytes().to_vec()));
    }

    /// The value of an entry.
    pub(crate) fn get(&self, index: u16, sub: u8) -> Option<u32> {
        self.find(index, sub).map(|e| e.value)
    }

    fn find(&self, index: u16, sub: u8) -> Option<&Entry> {
        self.entries
            .iter()
            .find(|e| (e.index, e.sub) == (index, sub))
    }

    /// Answers one CoE frame (`request` starts at the CoE header) with the replies the device
    /// puts into its input mailbox one after the other (each at most `room` bytes): one SDO
    /// reply, or one SDO information reply or its fragments. No reply for a service this
    /// server does not offer (emergencies, segmented transfers): the device then answers
    /// nothing.
    pub(crate) fn serve_mailbox(&mut self, request: &[u8], room: usize) -> Vec<Vec<u8>> {
        match request {
            [a, b, ..] if u16::from_le_bytes([*a, *b]) >> 12 == SDO_INFORMATION => {
                self.serve_info(request, room)
            }
            _ => self.serve(request, room).into_iter().collect(),
        }
    }

    /// Answers one CoE frame (`request` starts at the CoE header) with a reply of at most
    /// `room` bytes; `None` for a service this server does not offer here (SDO information
    /// goes to [`Dictionary::serve_info`] through [`Dictionary::serve_mailbox`]; emergencies):
    /// the device then answers nothing.
    pub(crate) fn serve(&mut self, request: &[u8], room: usize) -> Option<Vec<u8>> {
        if request.len() < 10 {
            return None;
        }
        let header = u16::from_le_bytes([request[0], request[1]]);
        if header >> 12 != SDO_REQUEST {
            return None;
        }
        let command = request[2];
        let index = u16::from_le_bytes([request[3], request[4]]);
        let sub = request[5];
        let data = u32::from_le_bytes([request[6], request[7], request[8], request[9]]);
        let reply = |command: u8, data: u32| {
            let mut r = (SDO_RESPONSE << 12).to_le_bytes().to_vec();
            r.push(command);
            r.extend_from_slice(&index.to_le_bytes());
            r.push(sub);
            r.extend_from_slice(&data.to_le_bytes());
            r
        };
        let abort = |code: u32| reply(0x80, code);
        if let Some((_, _, text)) = self.texts.iter().find(|t| (t.0, t.1) == (index, sub)) {
            return Some(match command >> 5 {
                // Normal upload, size indicated (0x41): the complete size, then the bytes.
                2 if 10 + text.len() <= room => {
                    let mut r = reply(0x41, text.len() as u32);
                    r.extend_from_slice(text);
                    r
                }
                // Too long for one mailbox: a real device would segment it.
                2 => abort(ABORT_NOT_SIMULATED),
                1 => abort(ABORT_READ_ONLY),
                _ => abort(ABORT_UNKNOWN_COMMAND),
            });
        }
        let entry = match self.find(index, sub) {
            Some(e) => *e,
            None if self.entries.iter().any(|e| e.index == index)
                || self.texts.iter().any(|t| t.0 == index) =>
            {
                return Some(abort(ABORT_NO_SUB_INDEX));
            }
            None => return Some(abort(ABORT_NO_OBJECT)),
        };
        // Command specifier in bits 5-7: 2 upload request, 1 download request.
        Some(match command >> 5 {
            2 => {
                // Expedited, size indicated: 0x4F / 0x4B / 0x43 for 1 / 2 / 4 bytes.
                let unused = 4 - entry.size;
                reply(0x43 | unused << 2, entry.value)
            }
            1 if command & 0x02 != 0 => {
                if !entry.writable {
                    abort(ABORT_READ_ONLY)
                } else {
                    let size = if command & 0x01 != 0 {
                        4 - (command >> 2 & 0x03)
                    } else {
                        4
                    };
                    let mask = if size >= 4 {
                        u32::MAX
                    } else {
                        (1u32 << (8 * size)) - 1
                    };
                    self.set(index, sub, data & mask, entry.size, true);
                    reply(0x60, 0)
                }
            }
            _ => abort(ABORT_UNKNOWN_COMMAND),
        })
    }
}

/// The EL3004's objects that ethercrab reads to reach OP (EMULATOR-NOTES §8, from ethercrab's
/// capture \[R1\]): no RxPDOs (1C12 empty), four TxPDOs 1A00/1A02/1A04/1A06 of ten entries
/// each (status bits and a 16-bit value per channel), plus the identity object 0x1018 and the
/// device name 0x1008 (the name its EEPROM gives, `sii-EL3004.txt`); and the settings it is
/// configured through, per channel `0x80n0` (n = 0..3, as its data sheet lists them):
/// `:02` presentation (u8: 0 signed, 1 unsigned, 2 absolute with MSB as sign), `:06` enable
/// filter (bool as u8) and `:15` filter settings (u16: 0 = 50 Hz FIR), all writable, all 0
/// after power-on; the inputs `0x60n0` the TxPDOs map, read-only and 0; and the names and
/// types the SDO information service gives ([`el3004_descriptions`]).
pub(crate) fn el3004(vendor: u32, product: u32, revision: u32) -> Dictionary {
    let mut d = Dictionary::default();
    d.text(0x1008, "EL3004");
    d.record(0x1018, &[vendor, product, revision, 0], 4, false);
    d.record(0x1C12, &[], 2, true);
    d.record(0x1C13, &[0x1A00, 0x1A02, 0x1A04, 0x1A06], 2, true);
    for (n, pdo) in [0x1A00u16, 0x1A02, 0x1A04, 0x1A06].into_iter().enumerate() {
        // Mapping entries: bit length | sub << 8 | index << 16; a bare number is a gap.
        let base = 0x6000_0000 + 0x0010_0000 * n as u32;
        let map = [
            base | 0x0101,
            base | 0x0201,
            base | 0x0302,
            base | 0x0502,
            base | 0x0701,
            0x0000_0001,
            0x0000_0006,
            base | 0x0F01,
            base | 0x1001,
            base | 0x1110,
        ];
        d.record(pdo, &map, 4, false);
    }
    for ch in 0..4u16 {
        let settings = 0x8000 + 0x10 * ch;
        d.set(settings, 0, 0x15, 1, false);
        d.set(settings, 0x02, 0, 1, true);
        d.set(settings, 0x06, 0, 1, true);
        d.set(settings, 0x15, 0, 2, true);
        // The inputs each channel's TxPDO maps, read-only (0 here: the simulated terminal
        // measures nothing).
        let inputs = 0x6000 + 0x10 * ch;
        d.set(inputs, 0, 0x11, 1, false);
        for (sub, size) in [(1, 1), (2, 1), (3, 1), (5, 1), (7, 1), (0x0F, 1), (0x10, 1)] {
            d.set(inputs, sub, 0, size, false);
        }
        d.set(inputs, 0x11, 0, 2, false);
    }
    el3004_descriptions(&mut d);
    d
}

/// The EL3004's object and entry names and types as its SDO information service gives them:
/// Beckhoff's EL30xx documentation ("Object description and parameterization": 0x1008
/// "Device name", 0x1018 "Identity", 0x1A0n "AI TxPDO-Map Standard Ch.n", 0x1C12/0x1C13
/// "RxPDO assign"/"TxPDO assign", 0x60n0 "AI Inputs Ch.n" with "Underrange" ... "Value"
/// (INT), 0x80n0 "AI Settings Ch.n"); see `data/README.md`.
fn el3004_descriptions(d: &mut Dictionary) {
    use deftype::*;
    let bits = |text: &str| 8 * text.len() as u16;
    d.describe_var(0x1008, "Device name", VISIBLE_STRING, bits("EL3004"), READ);
    let identity: Vec<(u8, &str, u16, u16, u16)> =
        ["Vendor ID", "Product code", "Revision", "Serial number"]
            .iter()
            .enumerate()
            .map(|(i, n)| (i as u8 + 1, *n, UNSIGNED32, 32, READ))
            .collect();
    d.describe_record(0x1018, "Identity", RECORD, IDENTITY, READ, &identity);
    let sub_names = sub_names();
    let assign = |n: usize| -> Vec<(u8, &str, u16, u16, u16)> {
        (0..n)
            .map(|i| {
                (
                    i as u8 + 1,
                    sub_names[i].as_str(),
                    UNSIGNED16,
                    16,
                    READ_WRITE,
                )
            })
            .collect()
    };
    d.describe_record(0x1C12, "RxPDO assign", ARRAY, UNSIGNED16, READ_WRITE, &[]);
    d.describe_record(
        0x1C13,
        "TxPDO assign",
        ARRAY,
        UNSIGNED16,
        READ_WRITE,
        &assign(4),
    );
    for ch in 0..4u16 {
        let n = ch + 1;
        let map: Vec<(u8, &str, u16, u16, u16)> = (0..10)
            .map(|i| (i as u8 + 1, sub_names[i].as_str(), UNSIGNED32, 32, READ))
            .collect();
        let pdo = 0x1A00 + 2 * ch;
        let name = format!("AI TxPDO-Map Standard Ch.{n}");
        d.describe_record(pdo, &name, RECORD, PDO_MAPPING, READ, &map);
        let tx = READ | TX_MAPPABLE;
        let inputs = [
            (0x01, "Underrange", BOOLEAN, 1, tx),
            (0x02, "Overrange", BOOLEAN, 1, tx),
            (0x03, "Limit 1", BIT2, 2, tx),
            (0x05, "Limit 2", BIT2, 2, tx),
            (0x07, "Error", BOOLEAN, 1, tx),
            (0x0F, "TxPDO State", BOOLEAN, 1, tx),
            (0x10, "TxPDO Toggle", BOOLEAN, 1, tx),
            (0x11, "Value", INTEGER16, 16, tx),
        ];
        let name = format!("AI Inputs Ch.{n}");
        d.describe_record(0x6000 + 0x10 * ch, &name, RECORD, 0, READ, &inputs);
        let settings = [
            (0x02, "Presentation", BIT3, 3, READ_WRITE),
            (0x06, "Enable filter", BOOLEAN, 1, READ_WRITE),
            (0x15, "Filter settings", UNSIGNED16, 16, READ_WRITE),
        ];
        let name = format!("AI Settings Ch.{n}");
        d.describe_record(0x8000 + 0x10 * ch, &name, RECORD, 0, READ, &settings);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Room for a reply in the EL3004's 128-byte input mailbox, after its 6-byte header.
    const ROOM: usize = 122;

    fn request(command: u8, index: u16, sub: u8, data: u32) -> Vec<u8> {
        let mut r = (SDO_REQUEST << 12).to_le_bytes().to_vec();
        r.push(command);
        r.extend_from_slice(&index.to_le_bytes());
        r.push(sub);
        r.extend_from_slice(&data.to_le_bytes());
        r
    }

    #[test]
    fn expedited_uploads_give_the_size_in_the_command_byte() {
        let mut d = el3004(2, 0x0BBC_3052, 0x0015_0000);
        let r = d.serve(&request(0x40, 0x1C13, 0, 0), ROOM).unwrap();
        assert_eq!(r, [0x00, 0x30, 0x4F, 0x13, 0x1C, 0, 4, 0, 0, 0]);
        let r = d.serve(&request(0x40, 0x1C13, 2, 0), ROOM).unwrap();
        assert_eq!(r[2], 0x4B);
        assert_eq!(r[6..8], [0x02, 0x1A]);
        let r = d.serve(&request(0x40, 0x1A02, 10, 0), ROOM).unwrap();
        assert_eq!((r[2], &r[6..]), (0x43, &[0x10, 0x11, 0x10, 0x60][..]));
    }

    #[test]
    fn downloads_change_writable_objects_and_abort_on_others() {
        let mut d = el3004(2, 0x0BBC_3052, 0x0015_0000);
        let r = d.serve(&request(0x2F, 0x1C13, 0, 0), ROOM).unwrap();
        assert_eq!(r[2], 0x60);
        assert_eq!(d.get(0x1C13, 0), Some(0));
        let r = d.serve(&request(0x2F, 0x1A00, 0, 0), ROOM).unwrap();
        assert_eq!((r[2], &r[6..]), (0x80, &0x0601_0002u32.to_le_bytes()[..]));
        let r = d.serve(&request(0x40, 0x2000, 0, 0), ROOM).unwrap();
        assert_eq!(&r[6..], &0x0602_0000u32.to_le_bytes());
    }

    #[test]
    fn a_string_object_is_uploaded_the_normal_way_with_its_complete_size() {
        let mut d = el3004(2, 0x0BBC_3052, 0x0015_0000);
        let r = d.serve(&request(0x40, 0x1008, 0, 0), ROOM).unwrap();
        assert_eq!(r[..6], [0x00, 0x30, 0x41, 0x08, 0x10, 0]);
        assert_eq!(r[6..10], 6u32.to_le_bytes(), "the complete size");
        assert_eq!(&r[10..], b"EL3004");
        // Without room for it in one mailbox (a real device would segment): an abort.
        let r = d.serve(&request(0x40, 0x1008, 0, 0), 15).unwrap();
        assert_eq!((r[2], &r[6..]), (0x80, &0x0800_0000u32.to_le_bytes()[..]));
        let r = d.serve(&request(0x2F, 0x1008, 0, 0), ROOM).unwrap();
        assert_eq!((r[2], &r[6..]), (0x80, &0x0601_0002u32.to_le_bytes()[..]));
        let r = d.serve(&request(0x40, 0x1008, 1, 0), ROOM).unwrap();
        assert_eq!(&r[6..], &0x0609_0011u32.to_le_bytes(), "no sub-index 1");
    }
}
