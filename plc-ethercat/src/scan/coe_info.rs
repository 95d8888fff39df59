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
//! Device data is hostile: every wait ends at a deadline, at most [`MAX_FRAGMENTS`] fragments
//! and [`MAX_ANSWER`] bytes make one answer, lengths are checked against the mailbox, an
//! answer must be for the object asked about, and nothing panics. What cannot be used is a
//! [`Failure`], after which the entry (or the whole device) keeps the name the scan gives an
//! entry without one.
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

use ethercrab::{RegisterAddress, SubDevice, SubDeviceRef};
use plc_rules::bus::scan::ScannedEntry;
use plc_rules::bus::sii::{Sii, SmUsage};
use std::collections::HashMap;
use std::time::{Duration, Instant};

/// Most fragments of one answer. An entry or object description fits one mailbox of any
/// real device; a few fragments are allowed for devices with tiny mailboxes.
pub const MAX_FRAGMENTS: usize = 16;

/// Most bytes of one answer's data (a description is a few dozen bytes and a name).
pub const MAX_ANSWER: usize = 4096;

/// Longest name taken from a device (ETG object names are a few dozen characters); a longer
/// one is not used.
pub const MAX_NAME: usize = 128;

/// Mailbox header (6 bytes), CoE header (2), SDO information header (4).
const MAILBOX_HEADER: usize = 6;
const INFO_HEADERS: usize = 6;

/// Mailbox types (mailbox header byte 5, bits 0-3): 0 a mailbox error reply, 3 CoE.
const MAILBOX_ERROR: u8 = 0;
const MAILBOX_COE: u8 = 3;

/// CoE services (CoE header bits 12-15): 1 emergency, 8 SDO information.
const COE_EMERGENCY: u16 = 1;
const COE_SDO_INFO: u16 = 8;

/// SDO information opcodes (ETG.1000.6 §5.6.3).
const GET_OBJECT_REQUEST: u8 = 0x03;
const GET_OBJECT_RESPONSE: u8 = 0x04;
const GET_ENTRY_REQUEST: u8 = 0x05;
const GET_ENTRY_RESPONSE: u8 = 0x06;
const INFO_ERROR: u8 = 0x07;

/// Emergencies a device may put between the fragments of an answer before the answer is
/// given up.
const MAX_EMERGENCIES: usize = 4;

/// SyncManager status bit 3: "mailbox full". (A SyncManager's registers, ethercrab's
/// `RegisterAddress::sync_manager(n)`: start u16, length u16, control, status, activate, PDI
/// control.)
const SM_MAILBOX_FULL: u8 = 0x08;

/// Pause between two polls of a SyncManager status.
const POLL: Duration = Duration::from_micros(200);

/// Why a description could not be used.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// Only this object or entry: the device answered with an SDO Info Error (its abort
    /// code), or its answer is unusable (a name too long). Other entries are still asked.
    Entry(String),
    /// The whole device: no answer in time, a mailbox error reply (no SDO information
    /// service), or an answer that breaks the protocol (a length beyond the mailbox, too many
    /// fragments, an answer for another object). It is not asked again.
    Device(String),
}

/// A mailbox that carries one request frame to a device and its answer frames back.
pub trait Mailbox {
    /// Bytes the device's input mailbox holds, its 6-byte header included.
    fn capacity(&self) -> usize;

    /// Sends one request frame (mailbox header included).
    fn send(&mut self, frame: &[u8]) -> impl Future<Output = Result<(), String>>;

    /// The next frame the device puts into its input mailbox (the whole buffer), or an error
    /// when none comes in time.
    fn receive(&mut self) -> impl Future<Output = Result<Vec<u8>, String>>;
}

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

/// The mailbox counter of this exchange: see the module documentation.
#[derive(Debug, Default)]
pub struct Counter(u8);

impl Counter {
    /// The counter for the next request: 0 first, then 1..=7 round.
    fn next(&mut self) -> u8 {
        let c = self.0;
        self.0 = if c >= 7 { 1 } else { c + 1 };
        c
    }
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

/// Sends one SDO information request (`opcode`, `data`) and gathers the data of its answer
/// (opcode `expected`) from every fragment.
async fn exchange(
    mailbox: &mut impl Mailbox,
    counter: &mut Counter,
    (opcode, expected): (u8, u8),
    data: &[u8],
) -> Result<Vec<u8>, Failure> {
    let capacity = mailbox.capacity();
    let length = (2 + 4 + data.len()) as u16;
    let mut frame = length.to_le_bytes().to_vec();
    frame.extend_from_slice(&[0, 0, 0, MAILBOX_COE | counter.next() << 4]);
    frame.extend_from_slice(&(COE_SDO_INFO << 12).to_le_bytes());
    frame.extend_from_slice(&[opcode, 0, 0, 0]);
    frame.extend_from_slice(data);
    mailbox.send(&frame).await.map_err(Failure::Device)?;

    let mut answer = Vec::new();
    let mut last_left: Option<u16> = None;
    let (mut fragments, mut emergencies) = (0, 0);
    loop {
        let reply = mailbox.receive().await.map_err(Failure::Device)?;
        let Some(&[lo, hi, _, _, _, kind]) = reply.get(..MAILBOX_HEADER) else {
            return Err(Failure::Device(format!(
                "a {}-byte answer, shorter than a mailbox header",
                reply.len()
            )));
        };
        let stated = usize::from(u16::from_le_bytes([lo, hi]));
        let room = capacity.min(reply.len()).saturating_sub(MAILBOX_HEADER);
        if stated > room {
            return Err(Failure::Device(format!(
                "an answer states {stated} bytes, more than the {room} its mailbox holds"
            )));
        }
        let body = &reply[MAILBOX_HEADER..MAILBOX_HEADER + stated];
        match kind & 0x0F {
            MAILBOX_COE => {}
            MAILBOX_ERROR => {
                let code = body
                    .get(2..4)
                    .map_or(0, |c| u16::from_le_bytes([c[0], c[1]]));
                return Err(Failure::Device(format!(
                    "mailbox error {code:#06x}: no SDO information service"
                )));
            }
            other => {
                return Err(Failure::Device(format!(
                    "an answer of mailbox type {other}, not CoE"
                )));
            }
        }
        let Some(&[c0, c1, op, _, l0, l1]) = body.get(..INFO_HEADERS) else {
            return Err(Failure::Device(format!(
                "a {stated}-byte CoE answer, shorter than its headers"
            )));
        };
        match u16::from_le_bytes([c0, c1]) >> 12 {
            COE_SDO_INFO => {}
            COE_EMERGENCY if emergencies < MAX_EMERGENCIES => {
                // An emergency may come between two mailbox services: not the answer.
                emergencies += 1;
                continue;
            }
            service => {
                return Err(Failure::Device(format!(
                    "an answer of CoE service {service}, not SDO information"
                )));
            }
        }
        let (incomplete, left) = (op & 0x80 != 0, u16::from_le_bytes([l0, l1]));
        if op & 0x7F == INFO_ERROR {
            let code = body
                .get(INFO_HEADERS..INFO_HEADERS + 4)
                .map_or(0, |c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]));
            return Err(Failure::Entry(format!(
                "SDO information error, abort code {code:#010x}"
            )));
        }
        if op & 0x7F != expected {
            return Err(Failure::Device(format!(
                "asked with opcode {opcode:#04x}, answered with {:#04x}",
                op & 0x7F
            )));
        }
        if let Some(before) = last_left
            && Some(left) != before.checked_sub(1)
        {
            return Err(Failure::Device(format!(
                "a fragment says {left} more follow after one that said {before}"
            )));
        }
        fragments += 1;
        answer.extend_from_slice(&body[INFO_HEADERS..]);
        if answer.len() > MAX_ANSWER {
            return Err(Failure::Device(format!(
                "an answer of more than {MAX_ANSWER} bytes"
            )));
        }
        if !incomplete {
            return Ok(answer);
        }
        if fragments >= MAX_FRAGMENTS {
            return Err(Failure::Device(format!(
                "an answer in more than {MAX_FRAGMENTS} fragments"
            )));
        }
        last_left = Some(left);
    }
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

/// One mailbox SyncManager as ethercrab configured it.
#[derive(Clone, Copy, Debug)]
struct Sm {
    /// 0..=15, which ethercrab's SyncManager register addresses take.
    index: u8,
    start: u16,
    len: u16,
}

/// A SubDevice's mailbox through ethercrab's register access.
pub struct EscMailbox<'a, 'md> {
    sd: &'a SubDeviceRef<'md, &'md SubDevice>,
    out: Sm,
    inp: Sm,
    timeout: Duration,
}

impl<'a, 'md> EscMailbox<'a, 'md> {
    /// The mailbox of `sd`: the SyncManagers its EEPROM names as mailboxes, with the start
    /// and length ethercrab configured in their registers. Each wait is bounded by `timeout`.
    pub async fn new(
        sd: &'a SubDeviceRef<'md, &'md SubDevice>,
        sii: &Sii,
        timeout: Duration,
    ) -> Result<Self, String> {
        // An ESC has at most 16 SyncManagers (registers 0x0800-0x087F); an EEPROM that puts
        // the mailbox beyond them is not believed.
        let find = |usage: SmUsage| {
            sii.sync_managers
                .iter()
                .position(|s| s.usage == usage)
                .filter(|&i| i < 16)
                .and_then(|i| u8::try_from(i).ok())
                .ok_or_else(|| format!("its EEPROM names no {usage:?} SyncManager among 0-15"))
        };
        let (out, inp) = (find(SmUsage::MailboxOut)?, find(SmUsage::MailboxIn)?);
        let mut sms = [Sm {
            index: 0,
            start: 0,
            len: 0,
        }; 2];
        for (slot, index) in sms.iter_mut().zip([out, inp]) {
            let r: [u8; 8] = sd
                .register_read(RegisterAddress::sync_manager(index))
                .await
                .map_err(|e| format!("reading SyncManager {index}: {e}"))?;
            let (start, len) = (
                u16::from_le_bytes([r[0], r[1]]),
                u16::from_le_bytes([r[2], r[3]]),
            );
            // Mode bits 0-1 = 0b10 (mailbox), activate bit 0: configured and enabled.
            if r[4] & 0x03 != 0x02 || r[6] & 0x01 == 0 || usize::from(len) < 16 {
                return Err(format!(
                    "SyncManager {index} is not an enabled mailbox of at least 16 bytes"
                ));
            }
            *slot = Sm { index, start, len };
        }
        Ok(EscMailbox {
            sd,
            out: sms[0],
            inp: sms[1],
            timeout,
        })
    }

    async fn status(&self, sm: Sm) -> Result<u8, String> {
        self.sd
            .register_read::<u8>(RegisterAddress::sync_manager_status(sm.index))
            .await
            .map_err(|e| format!("reading SyncManager {} status: {e}", sm.index))
    }

    /// Waits until SyncManager `sm` is `full` (or not), at most the timeout.
    async fn wait(&self, sm: Sm, full: bool, what: &str) -> Result<(), String> {
        let deadline = Instant::now() + self.timeout;
        loop {
            if (self.status(sm).await? & SM_MAILBOX_FULL != 0) == full {
                return Ok(());
            }
            if Instant::now() >= deadline {
                return Err(format!("{what} within {} ms", self.timeout.as_millis()));
            }
            async_io::Timer::after(POLL).await;
        }
    }
}

/// Writes `bytes` at `at` in ascending chunks of fixed sizes (ethercrab's register access
/// takes arrays), so the last byte is written last.
async fn write_bytes(
    sd: &SubDeviceRef<'_, &SubDevice>,
    at: u16,
    bytes: &[u8],
) -> Result<(), String> {
    let mut done = 0;
    while done < bytes.len() {
        let rest = &bytes[done..];
        let a = at
            .checked_add(done as u16)
            .ok_or("mailbox beyond the ESC's address space")?;
        let n = match rest.len() {
            256.. => write_chunk::<256>(sd, a, rest).await?,
            64.. => write_chunk::<64>(sd, a, rest).await?,
            16.. => write_chunk::<16>(sd, a, rest).await?,
            4.. => write_chunk::<4>(sd, a, rest).await?,
            _ => write_chunk::<1>(sd, a, rest).await?,
        };
        done += n;
    }
    Ok(())
}

async fn write_chunk<const N: usize>(
    sd: &SubDeviceRef<'_, &SubDevice>,
    at: u16,
    rest: &[u8],
) -> Result<usize, String> {
    let mut chunk = [0u8; N];
    chunk.copy_from_slice(&rest[..N]);
    sd.register_write(at, chunk)
        .await
        .map_err(|e| format!("writing the mailbox at {at:#06x}: {e}"))?;
    Ok(N)
}

/// Reads `len` bytes at `at` in ascending chunks, so the last byte is read last.
async fn read_bytes(
    sd: &SubDeviceRef<'_, &SubDevice>,
    at: u16,
    len: usize,
) -> Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(len);
    while out.len() < len {
        let a = at
            .checked_add(out.len() as u16)
            .ok_or("mailbox beyond the ESC's address space")?;
        let read = |e: ethercrab::error::Error| format!("reading the mailbox at {a:#06x}: {e}");
        match len - out.len() {
            256.. => out.extend(sd.register_read::<[u8; 256]>(a).await.map_err(read)?),
            64.. => out.extend(sd.register_read::<[u8; 64]>(a).await.map_err(read)?),
            16.. => out.extend(sd.register_read::<[u8; 16]>(a).await.map_err(read)?),
            4.. => out.extend(sd.register_read::<[u8; 4]>(a).await.map_err(read)?),
            _ => out.extend(sd.register_read::<[u8; 1]>(a).await.map_err(read)?),
        }
    }
    Ok(out)
}

impl Mailbox for EscMailbox<'_, '_> {
    fn capacity(&self) -> usize {
        usize::from(self.inp.len)
    }

    async fn send(&mut self, frame: &[u8]) -> Result<(), String> {
        let len = usize::from(self.out.len);
        if frame.len() > len {
            return Err(format!(
                "a {}-byte request does not fit the {len}-byte mailbox",
                frame.len()
            ));
        }
        self.wait(
            self.out,
            false,
            "the device did not take its previous request",
        )
        .await?;
        // The whole buffer, zero padded, as ethercrab writes it: the ESC hands it over when
        // its last byte is written.
        let mut padded = frame.to_vec();
        padded.resize(len, 0);
        write_bytes(self.sd, self.out.start, &padded).await
    }

    async fn receive(&mut self) -> Result<Vec<u8>, String> {
        self.wait(self.inp, true, "no answer").await?;
        read_bytes(self.sd, self.inp.start, usize::from(self.inp.len)).await
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use async_io::block_on;
    use std::collections::VecDeque;

    /// A device that answers from a script.
    struct Scripted {
        capacity: usize,
        sent: Vec<Vec<u8>>,
        replies: VecDeque<Vec<u8>>,
        /// Answer this frame for ever once the script is through.
        endless: Option<Vec<u8>>,
    }

    impl Scripted {
        fn new(replies: Vec<Vec<u8>>) -> Self {
            Scripted {
                capacity: 128,
                sent: Vec::new(),
                replies: replies.into(),
                endless: None,
            }
        }
    }

    impl Mailbox for Scripted {
        fn capacity(&self) -> usize {
            self.capacity
        }
        async fn send(&mut self, frame: &[u8]) -> Result<(), String> {
            self.sent.push(frame.to_vec());
            Ok(())
        }
        async fn receive(&mut self) -> Result<Vec<u8>, String> {
            match self.replies.pop_front().or_else(|| self.endless.clone()) {
                Some(mut r) => {
                    r.resize(self.capacity.max(r.len()), 0);
                    Ok(r)
                }
                None => Err("no answer within 1000 ms".into()),
            }
        }
    }

    /// A CoE SDO information frame: mailbox header (stated length `stated`, or the real one),
    /// CoE header, info header, data.
    fn frame(op: u8, left: u16, data: &[u8], stated: Option<u16>) -> Vec<u8> {
        let len = stated.unwrap_or((6 + data.len()) as u16);
        let mut f = len.to_le_bytes().to_vec();
        f.extend_from_slice(&[0, 0, 0, 0x13]);
        f.extend_from_slice(&(8u16 << 12).to_le_bytes());
        f.extend_from_slice(&[op, 0]);
        f.extend_from_slice(&left.to_le_bytes());
        f.extend_from_slice(data);
        f
    }

    fn entry(index: u16, sub: u8, ty: u16, bits: u16, name: &str) -> Vec<u8> {
        let mut d = index.to_le_bytes().to_vec();
        d.extend_from_slice(&[sub, 0]);
        d.extend_from_slice(&ty.to_le_bytes());
        d.extend_from_slice(&bits.to_le_bytes());
        d.extend_from_slice(&0x0087u16.to_le_bytes());
        d.extend_from_slice(name.as_bytes());
        d
    }

    #[test]
    fn an_entry_description_gives_name_type_and_bits_and_the_counter_starts_at_0() {
        let mut m = Scripted::new(vec![frame(
            0x06,
            0,
            &entry(0x6000, 0x11, 3, 16, "Value"),
            None,
        )]);
        let mut c = Counter::default();
        let d = block_on(describe_entry(&mut m, &mut c, 0x6000, 0x11)).unwrap();
        assert_eq!(
            d,
            Description {
                name: "Value".into(),
                data_type: 3,
                bits: 16
            }
        );
        let sent = &m.sent[0];
        assert_eq!(sent[..6], [10, 0, 0, 0, 0, 0x03], "CoE, counter 0");
        assert_eq!(sent[6..], [0x00, 0x80, 0x05, 0, 0, 0, 0x00, 0x60, 0x11, 0]);
        assert_eq!((c.next(), c.next()), (1, 2));
    }

    #[test]
    fn counters_after_the_first_cycle_through_1_to_7() {
        let mut c = Counter::default();
        let got: Vec<u8> = (0..10).map(|_| c.next()).collect();
        assert_eq!(got, [0, 1, 2, 3, 4, 5, 6, 7, 1, 2]);
    }

    #[test]
    fn an_entry_without_a_name_takes_its_objects_name_and_fragments_are_joined() {
        let whole = entry(0x6040, 0, 6, 16, "");
        let mut object = 0x6040u16.to_le_bytes().to_vec();
        object.extend_from_slice(&[6, 0, 0, 7]);
        object.extend_from_slice(b"Controlword\0\0");
        let mut m = Scripted::new(vec![
            frame(0x86, 1, &whole[..5], None),
            frame(0x06, 0, &whole[5..], None),
            frame(0x04, 0, &object, None),
        ]);
        let d = block_on(describe_entry(&mut m, &mut Counter::default(), 0x6040, 0)).unwrap();
        assert_eq!((d.name.as_str(), d.data_type), ("Controlword", 6));
        assert_eq!(m.sent.len(), 2);
        assert_eq!(m.sent[1][5] >> 4, 1, "the second request counts on");
    }

    #[test]
    fn an_sdo_info_error_fails_the_entry_only() {
        let mut m = Scripted::new(vec![frame(0x07, 0, &0x0602_0000u32.to_le_bytes(), None)]);
        let err = block_on(describe_entry(&mut m, &mut Counter::default(), 0x6000, 1));
        assert_eq!(
            err,
            Err(Failure::Entry(
                "SDO information error, abort code 0x06020000".into()
            ))
        );
    }

    #[test]
    fn hostile_answers_fail_the_device_without_hanging() {
        let ask =
            |m: &mut Scripted| block_on(describe_entry(m, &mut Counter::default(), 0x6000, 0x11));
        let device = |r: Result<Description, Failure>| match r {
            Err(Failure::Device(why)) => why,
            other => panic!("{other:?}"),
        };
        // A length beyond the mailbox.
        let mut m = Scripted::new(vec![frame(0x06, 0, &[], Some(500))]);
        assert_eq!(
            device(ask(&mut m)),
            "an answer states 500 bytes, more than the 122 its mailbox holds"
        );
        // Endless fragments.
        let mut m = Scripted::new(Vec::new());
        m.endless = Some(frame(0x86, 3, &[0; 8], None));
        let why = device(ask(&mut m));
        assert_eq!(why, "a fragment says 3 more follow after one that said 3");
        let mut m = Scripted::new(
            (0..100)
                .map(|i| frame(0x86, 1000 - i, &[0; 8], None))
                .collect(),
        );
        assert_eq!(device(ask(&mut m)), "an answer in more than 16 fragments");
        // An answer about another object, a short one, no answer, a mailbox error reply.
        let mut m = Scripted::new(vec![frame(
            0x06,
            0,
            &entry(0x6010, 0x11, 3, 16, "Value"),
            None,
        )]);
        assert_eq!(
            device(ask(&mut m)),
            "asked for object 0x6000:11, the device described 0x6010:11"
        );
        let mut m = Scripted::new(vec![frame(0x06, 0, &[0, 0x60], None)]);
        assert!(device(ask(&mut m)).contains("shorter than its 10-byte head"));
        let mut m = Scripted::new(Vec::new());
        assert_eq!(device(ask(&mut m)), "no answer within 1000 ms");
        let mut m = Scripted::new(vec![vec![4, 0, 0, 0, 0, 0x10, 1, 0, 2, 0]]);
        assert!(device(ask(&mut m)).starts_with("mailbox error 0x0002"));
        // Any bytes at all: an error or a description, never a panic.
        for len in 0..40u8 {
            let garbage: Vec<u8> = (0..len).map(|i| i.wrapping_mul(37) ^ len).collect();
            let _ = ask(&mut Scripted::new(vec![garbage]));
        }
    }

    #[test]
    fn a_name_longer_than_the_limit_is_not_used_and_odd_bytes_become_question_marks() {
        let long = "x".repeat(MAX_NAME + 1);
        let mut m = Scripted::new(vec![frame(0x06, 0, &entry(0x6000, 1, 1, 1, &long), None)]);
        m.capacity = 1024;
        let r = block_on(describe_entry(&mut m, &mut Counter::default(), 0x6000, 1));
        assert!(matches!(r, Err(Failure::Entry(_))), "{r:?}");
        assert_eq!(text(b"Wert \xb5V\0\0", "x"), Ok("Wert ?V".to_string()));
    }
}
