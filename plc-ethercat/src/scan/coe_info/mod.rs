//! Entry names and data types from a SubDevice's CoE object dictionary, through the SDO
//! information service (ETG.1000.6 §5.6.3): Get Entry Description (opcode 0x05, answered by
//! 0x06) gives an entry's data type, bit length and name; where an entry has no name, Get
//! Object Description (0x03, answered by 0x04) gives its object's. The scan asks for them where
//! the EEPROM does not name a mapped entry (a terminal whose EEPROM has no PDO categories, a
//! drive whose mapping is set over CoE).
//!
//! ethercrab 0.7 offers only Get OD List of this service, so the exchange is done here, on
//! the SyncManager registers and mailbox buffers through ethercrab's raw register access, the
//! way ethercrab does its own SDO exchanges: wait until the output mailbox (the MainDevice's
//! write mailbox) is free, write the request over the mailbox's full length (the ESC hands the
//! buffer to the device when its last byte is written), poll the input mailbox's SyncManager
//! status until it is full, and read the whole buffer (the ESC frees it when its last byte is
//! read). An answer longer than the mailbox comes in fragments, each read in turn.
//!
//! Device data is hostile: every wait ends at a deadline, at most
//! [`MAX_FRAGMENTS`](mailbox::MAX_FRAGMENTS) fragments and [`MAX_ANSWER`](mailbox::MAX_ANSWER)
//! bytes make one answer, lengths are checked against the mailbox, an answer must be for the
//! object asked about, and nothing panics. What cannot be used is a [`Failure`], after which
//! the entry (or the whole device) keeps the name the scan gives an entry without one.
//!
//! **Mailbox counter.** Each mailbox request carries a counter (header byte 5, bits 4-6) by
//! which a device recognises a repeated request and may drop it. ethercrab keeps its counter
//! to itself (it cycles 1..=7), so this exchange keeps its own: its first request carries 0,
//! the counter's start value (ETG.1000.4), which ethercrab never sends and so can never repeat
//! ethercrab's last request to the device; later ones count 1..=7, so no two requests in a row
//! carry the same counter. The scan runs this exchange only after ethercrab's SDO uploads of
//! the device are done, and nothing uses the device's mailbox after it before the device goes
//! back to INIT (which resets its mailbox), so the two counters never meet. The simulated
//! devices echo whatever counter they get.
//!
//! The files, in layers: `mailbox` the carrier and what may fail, `exchange` builds a request
//! and gathers its answer's fragments, `esc` carries them through a real device's
//! SyncManagers, and this one reads the descriptions.

mod esc;
mod exchange;
mod mailbox;
#[cfg(test)]
mod tests;

pub use esc::EscMailbox;
pub use exchange::Counter;
use exchange::{
    GET_ENTRY_REQUEST, GET_ENTRY_RESPONSE, GET_OBJECT_REQUEST, GET_OBJECT_RESPONSE, exchange,
};
pub use mailbox::{Failure, Mailbox};
use plc_rules::bus::scan::ScannedEntry;
use std::collections::HashMap;

/// Longest name taken from a device (ETG object names are a few dozen characters); a longer
/// one is not used.
pub const MAX_NAME: usize = 128;

/// What Get Entry Description (or, for an unnamed entry, Get Object Description) tells of
/// one entry.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Description {
    /// Its name (the object's for an entry without one), printable ASCII (`?` for other
    /// bytes); empty if neither has a name.
    pub name: String,
    /// Its data type (DEFTYPE, ETG.1000.6 table 63, e.g. 0x0003 INTEGER16).
    pub data_type: u16,
    /// Its bit length as the dictionary states it.
    pub bits: u16,
}

/// The description of `index`:`sub`, asked through `mailbox`.
pub async fn describe_entry(
    mailbox: &mut impl Mailbox,
    counter: &mut Counter,
    index: u16,
    sub: u8,
) -> Result<Description, Failure> {
    let [lo, hi] = index.to_le_bytes();
    // Value info 0: no unit, default, minimum or maximum, only what every answer carries.
    let data = exchange(
        mailbox,
        counter,
        (GET_ENTRY_REQUEST, GET_ENTRY_RESPONSE),
        &[lo, hi, sub, 0],
    )
    .await?;
    let what = format!("object {index:#06x}:{sub:02x}");
    let Some(&[ilo, ihi, got_sub, value_info, tlo, thi, blo, bhi, _, _]) = data.get(..10) else {
        return Err(Failure::Device(format!(
            "the description of {what} is {} bytes, shorter than its 10-byte head",
            data.len()
        )));
    };
    if (u16::from_le_bytes([ilo, ihi]), got_sub) != (index, sub) {
        return Err(Failure::Device(format!(
            "asked for {what}, the device described {:#06x}:{got_sub:02x}",
            u16::from_le_bytes([ilo, ihi])
        )));
    }
    let (data_type, bits) = (
        u16::from_le_bytes([tlo, thi]),
        u16::from_le_bytes([blo, bhi]),
    );
    // Optional fields the device sent though none were asked for: unit type (2 bytes), then
    // default, minimum and maximum value (each the entry's size).
    let size = usize::from(bits).div_ceil(8);
    let skip = [(0x08, 2), (0x10, size), (0x20, size), (0x40, size)]
        .iter()
        .filter(|(bit, _)| value_info & bit != 0)
        .map(|(_, n)| n)
        .sum::<usize>();
    let name = data.get(10 + skip..).unwrap_or_default();
    let mut name = text(name, &what)?;
    if name.is_empty() {
        name = object_name(mailbox, counter, index).await?;
    }
    Ok(Description {
        name,
        data_type,
        bits,
    })
}

/// The name of object `index` (Get Object Description).
async fn object_name(
    mailbox: &mut impl Mailbox,
    counter: &mut Counter,
    index: u16,
) -> Result<String, Failure> {
    let data = exchange(
        mailbox,
        counter,
        (GET_OBJECT_REQUEST, GET_OBJECT_RESPONSE),
        &index.to_le_bytes(),
    )
    .await?;
    let what = format!("object {index:#06x}");
    match data.get(..6) {
        Some(&[lo, hi, ..]) if u16::from_le_bytes([lo, hi]) == index => text(&data[6..], &what),
        Some(&[lo, hi, ..]) => Err(Failure::Device(format!(
            "asked for {what}, the device described {:#06x}",
            u16::from_le_bytes([lo, hi])
        ))),
        _ => Err(Failure::Device(format!(
            "the description of {what} is {} bytes, shorter than its 6-byte head",
            data.len()
        ))),
    }
}

/// A name from the device: printable ASCII kept, other bytes `?`, trailing NULs and blanks
/// dropped (some devices pad names).
fn text(bytes: &[u8], what: &str) -> Result<String, Failure> {
    let end = bytes.iter().rposition(|&b| b != 0).map_or(0, |i| i + 1);
    let bytes = &bytes[..end];
    if bytes.len() > MAX_NAME {
        return Err(Failure::Entry(format!(
            "the name of {what} is {} bytes long, more than {MAX_NAME}",
            bytes.len()
        )));
    }
    let name: String = bytes
        .iter()
        .map(|&b| {
            if (0x20..0x7F).contains(&b) {
                b as char
            } else {
                '?'
            }
        })
        .collect();
    Ok(name.trim().to_owned())
}
/// Names and types the entries in `entries` that have no name from their descriptions in the
/// device's dictionary: the name where the EEPROM gives none, the data type where it gives
/// none (DEFTYPEs above 0xFF, which no IEC type matches, are left out). Each object entry is
/// asked once. Returns why the device stopped being asked, if it did (the entries not yet
/// named keep no name).
pub async fn name_entries(
    mailbox: &mut impl Mailbox,
    entries: &mut [ScannedEntry],
) -> Option<String> {
    let mut counter = Counter::default();
    let mut known: HashMap<(u16, u8), Option<Description>> = HashMap::new();
    for e in entries.iter_mut() {
        if e.name.is_some() || e.index == 0 {
            continue;
        }
        let key = (e.index, e.subindex);
        let found = match known.entry(key) {
            std::collections::hash_map::Entry::Occupied(seen) => seen.into_mut(),
            std::collections::hash_map::Entry::Vacant(slot) => {
                let asked = describe_entry(mailbox, &mut counter, e.index, e.subindex).await;
                slot.insert(match asked {
                    Ok(d) => Some(d),
                    Err(Failure::Entry(why)) => {
                        log::debug!(
                            target: "plc_io::ethercat",
                            "scan: {:#06x}:{:02x}: {why}",
                            e.index,
                            e.subindex
                        );
                        None
                    }
                    Err(Failure::Device(why)) => return Some(why),
                })
            }
        };
        if let Some(d) = found {
            if !d.name.is_empty() {
                e.name = Some(d.name.clone());
            }
            if e.data_type.is_none() {
                e.data_type = u8::try_from(d.data_type).ok();
            }
        }
    }
    None
}
