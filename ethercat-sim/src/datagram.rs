//! EtherCAT frames: the Ethernet header, the EtherCAT header and the datagrams inside, checked
//! completely before any device sees them, so a malformed frame changes nothing.

/// EtherCAT's ethertype.
pub const ETHERTYPE: u16 = 0x88A4;

/// Ethernet header bytes (no VLAN tag: ethercrab and real masters send none).
const ETH_HEADER: usize = 14;
/// Datagram header bytes before the data: cmd, idx, address (4), flags (2), IRQ (2).
const DATAGRAM_HEADER: usize = 10;

/// Why a frame was not processed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Malformed {
    /// Shorter than the Ethernet and EtherCAT headers.
    TooShort,
    /// Another ethertype: not for the EtherCAT ring.
    NotEtherCat,
    /// The EtherCAT header's type is not 1 (datagrams).
    NotDatagrams,
    /// A length field points past the end of the frame.
    Truncated,
}

/// Datagram commands (ETG.1000.4 table 10).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// No operation.
    Nop,
    /// Auto-increment physical read.
    Aprd,
    /// Auto-increment physical write.
    Apwr,
    /// Auto-increment physical read-write.
    Aprw,
    /// Configured-address physical read.
    Fprd,
    /// Configured-address physical write.
    Fpwr,
    /// Configured-address physical read-write.
    Fprw,
    /// Broadcast read.
    Brd,
    /// Broadcast write.
    Bwr,
    /// Broadcast read-write.
    Brw,
    /// Logical read.
    Lrd,
    /// Logical write.
    Lwr,
    /// Logical read-write.
    Lrw,
    /// Auto-increment read, multiple write.
    Armw,
    /// Configured-address read, multiple write.
    Frmw,
    /// A code no ESC knows: the datagram passes unchanged.
    Unknown(u8),
}

impl Command {
    /// The command of a code.
    pub fn from_code(code: u8) -> Command {
        match code {
            0x00 => Command::Nop,
            0x01 => Command::Aprd,
            0x02 => Command::Apwr,
            0x03 => Command::Aprw,
            0x04 => Command::Fprd,
            0x05 => Command::Fpwr,
            0x06 => Command::Fprw,
            0x07 => Command::Brd,
            0x08 => Command::Bwr,
            0x09 => Command::Brw,
            0x0A => Command::Lrd,
            0x0B => Command::Lwr,
            0x0C => Command::Lrw,
            0x0D => Command::Armw,
            0x0E => Command::Frmw,
            other => Command::Unknown(other),
        }
    }
}

/// One datagram of a frame, as the devices of the ring see it.
#[derive(Debug)]
pub struct Datagram<'a> {
    /// The command.
    pub command: Command,
    /// Position (auto-increment), station address (configured) or low half of the logical
    /// address; devices change it on auto-increment and broadcast commands.
    pub adp: u16,
    /// Register address, or high half of the logical address.
    pub ado: u16,
    /// The data, read and written in place.
    pub data: &'a mut [u8],
    /// The working counter.
    pub wkc: u16,
}

impl Datagram<'_> {
    /// The 32-bit logical address of LRD/LWR/LRW.
    pub fn logical_address(&self) -> u32 {
        self.adp as u32 | (self.ado as u32) << 16
    }
}

/// Checks `frame` and returns the offset of each datagram.
fn layout(frame: &[u8]) -> Result<Vec<usize>, Malformed> {
    if frame.len() < ETH_HEADER + 2 {
        return Err(Malformed::TooShort);
    }
    if u16::from_be_bytes([frame[12], frame[13]]) != ETHERTYPE {
        return Err(Malformed::NotEtherCat);
    }
    let header = u16::from_le_bytes([frame[ETH_HEADER], frame[ETH_HEADER + 1]]);
    if header >> 12 != 1 {
        return Err(Malformed::NotDatagrams);
    }
    let end = ETH_HEADER + 2 + (header & 0x07FF) as usize;
    if end > frame.len() {
        return Err(Malformed::Truncated);
    }
    let mut offsets = Vec::new();
    let mut at = ETH_HEADER + 2;
    loop {
        if at + DATAGRAM_HEADER + 2 > end {
            return Err(Malformed::Truncated);
        }
        let flags = u16::from_le_bytes([frame[at + 6], frame[at + 7]]);
        let next = at + DATAGRAM_HEADER + (flags & 0x07FF) as usize + 2;
        if next > end {
            return Err(Malformed::Truncated);
        }
        offsets.push(at);
        at = next;
        if flags & 0x8000 == 0 {
            return Ok(offsets);
        }
    }
}

/// Runs `f` on every datagram of `frame` in order, writing back the address and working
/// counter it leaves. Nothing runs if the frame is malformed.
pub fn for_each(frame: &mut [u8], mut f: impl FnMut(&mut Datagram<'_>)) -> Result<(), Malformed> {
    for at in layout(frame)? {
        let (head, rest) = frame[at..].split_at_mut(DATAGRAM_HEADER);
        let len = (u16::from_le_bytes([head[6], head[7]]) & 0x07FF) as usize;
        let (data, tail) = rest.split_at_mut(len);
        let mut d = Datagram {
            command: Command::from_code(head[0]),
            adp: u16::from_le_bytes([head[2], head[3]]),
            ado: u16::from_le_bytes([head[4], head[5]]),
            data,
            wkc: u16::from_le_bytes([tail[0], tail[1]]),
        };
        f(&mut d);
        let (adp, wkc) = (d.adp, d.wkc);
        head[2..4].copy_from_slice(&adp.to_le_bytes());
        tail[..2].copy_from_slice(&wkc.to_le_bytes());
    }
    Ok(())
}

/// A frame from 10:10:10:10:10:10 with one datagram: command code `cmd` (ETG.1000.4 table
/// 10, e.g. 0x05 FPWR), address `adp`/`ado`, `data`, working counter 0. For tests that talk
/// to the ring without a MainDevice, or behind one's back as a second master would, through
/// [`SimBus::process_frame`](crate::SimBus::process_frame). The reply's data starts at byte
/// 26, its working counter follows it.
///
/// ```
/// use ethercat_sim::{Device, SimBus, datagram_frame};
/// let bus = SimBus::new(vec![Device::ek1100()]);
/// // APRD of the type register (0x0000) of the device at position 0.
/// let reply = bus.process_frame(&datagram_frame(0x01, 0, 0x0000, &[0])).unwrap();
/// assert_eq!(reply[26], 0x11, "an ESC of type 0x11");
/// assert_eq!(reply[27], 1, "one device answered");
/// ```
pub fn datagram_frame(cmd: u8, adp: u16, ado: u16, data: &[u8]) -> Vec<u8> {
    let mut f = vec![0xFF; 6];
    f.extend_from_slice(&[0x10; 6]);
    f.extend_from_slice(&ETHERTYPE.to_be_bytes());
    // EtherCAT header: length of the datagram (header, data, working counter), type 1.
    f.extend_from_slice(&(0x1000 | (DATAGRAM_HEADER + data.len() + 2) as u16).to_le_bytes());
    f.extend_from_slice(&[cmd, 0]);
    f.extend_from_slice(&adp.to_le_bytes());
    f.extend_from_slice(&ado.to_le_bytes());
    // Length; no round trip, no more datagrams.
    f.extend_from_slice(&(data.len() as u16).to_le_bytes());
    // IRQ.
    f.extend_from_slice(&[0, 0]);
    f.extend_from_slice(data);
    // Working counter.
    f.extend_from_slice(&[0, 0]);
    f
}

/// The reply a ring gives back: the first device sets bit 1 ("locally administered") of the
/// source MAC, so 10:10:10:10:10:10 becomes 12:10:10:10:10:10 (ethercrab drops frames that
/// still carry its own address), and a frame shorter than Ethernet's minimum is padded to 60
/// bytes as real SubDevices pad it.
pub fn finish_reply(frame: &mut Vec<u8>) {
    frame[6] |= 0x02;
    if frame.len() < 60 {
        frame.resize(60, 0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(datagrams: &[(u8, u16, u16, &[u8], bool)]) -> Vec<u8> {
        let mut f = vec![0xFF; 6];
        f.extend_from_slice(&[0x10; 6]);
        f.extend_from_slice(&ETHERTYPE.to_be_bytes());
        let body: usize = datagrams.iter().map(|d| 12 + d.3.len()).sum();
        f.extend_from_slice(&(0x1000 | body as u16).to_le_bytes());
        for &(cmd, adp, ado, data, more) in datagrams {
            f.extend_from_slice(&[cmd, 0]);
            f.extend_from_slice(&adp.to_le_bytes());
            f.extend_from_slice(&ado.to_le_bytes());
            let flags = data.len() as u16 | if more { 0x8000 } else { 0 };
            f.extend_from_slice(&flags.to_le_bytes());
            f.extend_from_slice(&[0, 0]);
            f.extend_from_slice(data);
            f.extend_from_slice(&[0, 0]);
        }
        f
    }

    #[test]
    fn datagrams_are_walked_in_order_and_updated_in_place() {
        let mut f = frame(&[
            (0x07, 0, 0, &[0][..], true),
            (0x04, 0x1000, 0x130, &[0, 0][..], false),
        ]);
        let mut seen = Vec::new();
        for_each(&mut f, |d| {
            seen.push(d.command);
            d.wkc = 7;
            d.adp += 1;
        })
        .unwrap();
        assert_eq!(seen, [Command::Brd, Command::Fprd]);
        assert_eq!(&f[16 + 2..16 + 4], &[1, 0]);
        assert_eq!(&f[f.len() - 2..], &[7, 0]);
    }

    #[test]
    fn malformed_frames_are_rejected_before_anything_runs() {
        let mut runs = 0;
        assert_eq!(for_each(&mut [], |_| runs += 1), Err(Malformed::TooShort));
        let mut f = frame(&[(0x07, 0, 0, &[0][..], true)]); // "more follows" but nothing follows
        assert_eq!(for_each(&mut f, |_| runs += 1), Err(Malformed::Truncated));
        let mut f = frame(&[(0x07, 0, 0, &[0][..], false)]);
        f[12] = 0x08;
        assert_eq!(for_each(&mut f, |_| runs += 1), Err(Malformed::NotEtherCat));
        let mut f = frame(&[(0x07, 0, 0, &[0][..], false)]);
        f[15] = 0x20;
        assert_eq!(
            for_each(&mut f, |_| runs += 1),
            Err(Malformed::NotDatagrams)
        );
        assert_eq!(runs, 0);
    }
}
