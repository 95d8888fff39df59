//! SII EEPROM images: parsing the word dumps in `data/`, reading the categories a MainDevice
//! uses (name, SyncManagers), and the ESC's EEPROM interface (registers 0x0500-0x050F) with
//! the timing real terminals show (EMULATOR-NOTES §4).

/// Words in an image (2 KiB, as the real dumps hold; word 0x3E = 0x000F).
pub const WORDS: usize = 1024;

/// How long a read keeps the busy bit set. Capture \[A\] shows busy up to 676 µs after the read
/// command and idle from 711 µs on (every device, every read), so polls see busy as on
/// hardware: a MainDevice that skips the busy check reads stale data here too.
pub const READ_BUSY_NS: u64 = 700_000;
/// How long a write keeps the busy bit set (capture \[B\]: idle 295 µs after one write, busy
/// 296.6 µs after another).
pub const WRITE_BUSY_NS: u64 = 297_000;
/// The EEPROM chip's internal write cycle: it does not acknowledge commands for this long
/// after a write, and the ESC reports a command error (bit 13). Capture \[B\] shows errors up
/// to 2.95 ms after a write and success from 3.56 ms on.
pub const WRITE_CYCLE_NS: u64 = 3_200_000;

/// Parses `WORDADDR: w0 w1 ... w7` lines. `????` (not captured) reads as 0 before the End
/// category and as 0xFFFF (erased EEPROM) after it, as EMULATOR-NOTES §10 advises.
pub fn parse(text: &str) -> Vec<u16> {
    let mut words = vec![None; WORDS];
    for line in text.lines() {
        let Some((addr, rest)) = line.split_once(':') else {
            continue;
        };
        let Ok(addr) = usize::from_str_radix(addr.trim(), 16) else {
            continue;
        };
        for (i, w) in rest.split_whitespace().enumerate() {
            if let (Some(slot), Ok(v)) = (words.get_mut(addr + i), u16::from_str_radix(w, 16)) {
                *slot = Some(v);
            }
        }
    }
    let end = end_of_categories(&words);
    let mut out: Vec<u16> = words
        .iter()
        .enumerate()
        .map(|(i, w)| w.unwrap_or(if i < end { 0 } else { 0xFFFF }))
        .collect();
    if out[0x3E] == 0 {
        out[0x3E] = 0x000F;
    }
    out
}

/// The word after the End category (0xFFFF header), following the category chain from 0x40.
fn end_of_categories(words: &[Option<u16>]) -> usize {
    let mut at = 0x40;
    while at + 1 < words.len() {
        match (words[at], words[at + 1]) {
            (Some(0xFFFF), _) => return at + 1,
            (Some(_), Some(len)) => at += 2 + len as usize,
            _ => return at,
        }
    }
    words.len()
}

/// Vendor, product and revision (words 0x08-0x0D).
pub fn identity(words: &[u16]) -> (u32, u32, u32) {
    let dword = |w: usize| {
        words.get(w).copied().unwrap_or(0) as u32
            | (words.get(w + 1).copied().unwrap_or(0) as u32) << 16
    };
    (dword(0x08), dword(0x0A), dword(0x0C))
}

/// Sets vendor, product and revision (words 0x08-0x0D).
pub fn set_identity(words: &mut [u16], vendor: u32, product: u32, revision: u32) {
    for (w, v) in [(0x08, vendor), (0x0A, product), (0x0C, revision)] {
        if let Some(pair) = words.get_mut(w..w + 2) {
            pair.copy_from_slice(&[v as u16, (v >> 16) as u16]);
        }
    }
}

/// The categories from word 0x40 on: (type, first data word, length in words).
pub fn categories(words: &[u16]) -> impl Iterator<Item = (u16, usize, usize)> + '_ {
    let mut at = 0x40;
    std::iter::from_fn(move || {
        let kind = *words.get(at)?;
        let len = *words.get(at + 1)? as usize;
        if kind == 0xFFFF {
            return None;
        }
        let item = (kind, at + 2, len);
        at += 2 + len;
        Some(item)
    })
}

/// The bytes of the first category of type `kind`.
fn category_bytes(words: &[u16], kind: u16) -> Option<Vec<u8>> {
    let (_, start, len) = categories(words).find(|c| c.0 == kind)?;
    let data = words.get(start..start + len)?;
    Some(data.iter().flat_map(|w| w.to_le_bytes()).collect())
}

/// The name a MainDevice shows: the General category's order-number string (ethercrab takes
/// `strings[byte 2]`, 1-based).
pub fn name(words: &[u16]) -> Option<String> {
    let general = category_bytes(words, 30)?;
    let index = *general.get(2)? as usize;
    let strings = category_bytes(words, 10)?;
    let mut rest = strings.get(1..)?;
    for i in 1..=index {
        let (&len, tail) = rest.split_first()?;
        let text = tail.get(..len as usize)?;
        if i == index {
            return Some(text.iter().map(|&b| b as char).collect());
        }
        rest = &tail[len as usize..];
    }
    None
}

/// A SyncManager as the SII's category 41 describes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SiiSyncManager {
    /// Physical start address.
    pub start: u16,
    /// Length in bytes (0 for some output terminals: the MainDevice sizes it from the PDOs).
    pub len: u16,
    /// Control byte (buffer type and direction).
    pub control: u8,
    /// Enable byte.
    pub enable: u8,
    /// 1 mailbox out, 2 mailbox in, 3 outputs, 4 inputs.
    pub kind: u8,
}

/// The SyncManagers of the SII, 8 bytes each.
pub fn sync_managers(words: &[u16]) -> Vec<SiiSyncManager> {
    let Some(bytes) = category_bytes(words, 41) else {
        return Vec::new();
    };
    bytes
        .chunks_exact(8)
        .map(|c| SiiSyncManager {
            start: u16::from_le_bytes([c[0], c[1]]),
            len: u16::from_le_bytes([c[2], c[3]]),
            control: c[4],
            enable: c[6],
            kind: c[7],
        })
        .collect()
}

/// What the EEPROM interface is doing.
#[derive(Clone, Copy, Debug)]
enum Pending {
    Read { address: usize, done_at: u64 },
    Write { done_at: u64 },
}

/// The ESC's EEPROM interface: commands, busy bit, errors, and the chip's write cycle.
#[derive(Clone, Debug)]
pub(crate) struct Eeprom {
    pub(crate) words: Vec<u16>,
    idle: u16,
    pending: Option<Pending>,
    error: u16,
    chip_busy_until: u64,
}

/// Control/status bits.
const BUSY: u16 = 0x8000;
const READ: u16 = 0x0100;
const WRITE: u16 = 0x0200;
const RELOAD: u16 = 0x0400;
const WRITE_ENABLE: u16 = 0x0001;
const COMMAND_ERROR: u16 = 0x2000;

/// What a finished command leaves for the ESC to put into its registers.
pub(crate) enum Completed {
    /// Nothing new.
    Nothing,
    /// Four words for 0x0508-0x050F.
    Data([u8; 8]),
}

impl Eeprom {
    pub(crate) fn new(words: Vec<u16>, idle: u16) -> Eeprom {
        Eeprom {
            words,
            idle,
            pending: None,
            error: 0,
            chip_busy_until: 0,
        }
    }

    /// Finishes a command whose time has come.
    pub(crate) fn tick(&mut self, now: u64) -> Completed {
        match self.pending {
            Some(Pending::Read { address, done_at }) if now >= done_at => {
                self.pending = None;
                let mut data = [0u8; 8];
                for (i, chunk) in data.chunks_exact_mut(2).enumerate() {
                    let w = self.words.get(address + i).copied().unwrap_or(0xFFFF);
                    chunk.copy_from_slice(&w.to_le_bytes());
                }
                Completed::Data(data)
            }
            Some(Pending::Write { done_at }) if now >= done_at => {
                self.pending = None;
                Completed::Nothing
            }
            _ => Completed::Nothing,
        }
    }

    /// The control/status register.
    pub(crate) fn status(&self) -> u16 {
        let command = match self.pending {
            Some(Pending::Read { .. }) => BUSY | READ,
            Some(Pending::Write { .. }) => BUSY | WRITE,
            None => 0,
        };
        self.idle | command | self.error
    }

    /// A write to the control register. Returns true for a reload (the ESC then reloads the
    /// registers it takes from the EEPROM, such as the station alias).
    pub(crate) fn command(&mut self, control: u16, address: u32, data: u16, now: u64) -> bool {
        if self.pending.is_some() {
            // The ESC ignores commands while busy.
            return false;
        }
        let command = control & (READ | WRITE | RELOAD);
        if command == 0 {
            return false;
        }
        self.error = 0;
        let address = address as usize;
        if now < self.chip_busy_until {
            // The chip is still writing and does not acknowledge (capture [B] F1211-1229).
            self.error = COMMAND_ERROR;
            return false;
        }
        match command {
            READ => {
                self.pending = Some(Pending::Read {
                    address,
                    done_at: now + READ_BUSY_NS,
                });
                false
            }
            WRITE if control & WRITE_ENABLE != 0 => {
                if let Some(w) = self.words.get_mut(address) {
                    *w = data;
                }
                self.pending = Some(Pending::Write {
                    done_at: now + WRITE_BUSY_NS,
                });
                self.chip_busy_until = now + WRITE_CYCLE_NS;
                false
            }
            RELOAD => true,
            _ => {
                // Two commands at once, or a write without write enable.
                self.error = COMMAND_ERROR;
                false
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ek1100_image_holds_its_identity_and_name() {
        let w = parse(include_str!("../data/sii-EK1100-full.txt"));
        assert_eq!(identity(&w), (2, 0x044C_2C52, 0x0012_0000));
        assert_eq!(w[0x3E], 0x000F);
        assert_eq!(name(&w).as_deref(), Some("EK1100"));
        assert!(sync_managers(&w).is_empty());
    }

    #[test]
    fn missing_words_read_as_zero_then_erased() {
        let w = parse(include_str!("../data/sii-EL1004.txt"));
        assert_eq!(identity(&w), (2, 0x03EC_3052, 0x0013_0000));
        assert_eq!(w[0x1A], 0);
        assert_eq!(w[0xC2], 0xFFFF);
        assert_eq!(w[0x200], 0xFFFF);
        assert_eq!(name(&w).as_deref(), Some("EL1004"));
    }

    #[test]
    fn sync_managers_come_from_category_41() {
        let w = parse(include_str!("../data/sii-EL2889-full.txt"));
        let sms = sync_managers(&w);
        assert_eq!(sms.len(), 2);
        assert_eq!(
            sms[1],
            SiiSyncManager {
                start: 0x0F01,
                len: 1,
                control: 0x44,
                enable: 0x09,
                kind: 3
            }
        );
    }

    #[test]
    fn a_read_is_busy_for_a_while_then_delivers_four_words() {
        let w = parse(include_str!("../data/sii-EK1100-full.txt"));
        let mut e = Eeprom::new(w, 0x0040);
        e.command(0x0100, 8, 0, 1_000);
        assert_eq!(e.status(), 0x8140);
        assert!(matches!(
            e.tick(1_000 + READ_BUSY_NS - 1),
            Completed::Nothing
        ));
        let Completed::Data(d) = e.tick(1_000 + READ_BUSY_NS) else {
            panic!("read not finished");
        };
        assert_eq!(d, [0x02, 0, 0, 0, 0x52, 0x2c, 0x4c, 0x04]); // [A] F111
        assert_eq!(e.status(), 0x0040);
    }

    #[test]
    fn commands_during_the_chip_write_cycle_fail_with_a_command_error() {
        let mut e = Eeprom::new(vec![0; WORDS], 0x0040);
        e.command(0x0201, 4, 0xABCD, 0);
        assert_eq!(e.status(), 0x8240);
        e.tick(WRITE_BUSY_NS);
        assert_eq!(e.status(), 0x0040);
        e.command(0x0201, 7, 0x0052, WRITE_CYCLE_NS - 1);
        assert_eq!(e.status(), 0x2040); // [B] F1212
        e.command(0x0201, 7, 0x0052, WRITE_CYCLE_NS);
        assert_eq!(e.status(), 0x8240);
        assert_eq!((e.words[4], e.words[7]), (0xABCD, 0x0052));
    }
}
