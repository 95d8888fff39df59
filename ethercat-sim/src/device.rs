//! One simulated SubDevice: the ESC's address space (registers and process RAM), its SII
//! EEPROM, its AL state machine, SyncManagers and FMMUs, as Beckhoff's ESCs without a
//! microcontroller behave (EMULATOR-NOTES §2, §4-§6).

use crate::sii;

/// Bytes of ESC address space modelled (registers 0x0000-0x0FFF and 4 KiB of process RAM).
const SPACE: usize = 0x2000;

/// AL states (low nibble of AL status 0x0130).
pub mod al {
    /// INIT.
    pub const INIT: u8 = 1;
    /// PRE-OP.
    pub const PRE_OP: u8 = 2;
    /// BOOT.
    pub const BOOT: u8 = 3;
    /// SAFE-OP.
    pub const SAFE_OP: u8 = 4;
    /// OP.
    pub const OP: u8 = 8;
    /// AL status code "invalid requested state change".
    pub const INVALID_STATE_CHANGE: u16 = 0x0011;
}

/// A SyncManager as the SII describes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SiiSyncManager {
    /// Physical start address.
    pub start: u16,
    /// Length in bytes (0 for some output terminals: ethercrab sizes it from the PDOs).
    pub len: u16,
    /// 3 outputs, 4 inputs, 1/2 mailbox.
    pub kind: u8,
}

/// A simulated EtherCAT SubDevice.
#[derive(Clone, Debug)]
pub struct Device {
    pub(crate) name: &'static str,
    pub(crate) mem: Vec<u8>,
    pub(crate) sii: Vec<u16>,
    pub(crate) fmmus: usize,
    pub(crate) sms: usize,
    sii_idle: u16,
    pub(crate) sync_managers: Vec<SiiSyncManager>,
    pub(crate) responding: bool,
    refuse: Option<(u8, u16)>,
}

impl Device {
    /// A device from its SII words and ESC facts: type byte (0x0000), FMMU and SM counts,
    /// and the idle value of the EEPROM control/status register (0x0040 or 0x0050).
    pub fn from_sii(
        name: &'static str,
        sii: Vec<u16>,
        esc_type: u8,
        fmmus: u8,
        sms: u8,
        sii_idle: u16,
    ) -> Device {
        let mut d = Device {
            name,
            mem: vec![0; SPACE],
            sync_managers: sync_managers(&sii),
            sii,
            fmmus: fmmus as usize,
            sms: sms as usize,
            sii_idle,
            responding: true,
            refuse: None,
        };
        d.mem[0x0000] = esc_type;
        d.mem[0x0004] = fmmus;
        d.mem[0x0005] = sms;
        d.mem[0x0006] = 1; // KiB of RAM
        // Features 0x0008: like the real devices (0x00FC) but without bit 2 "DC supported":
        // the simulator has no distributed clocks (ethercrab then skips DC configuration).
        d.set_u16(0x0008, 0x00F8);
        d.set_u16(0x0012, d.sii[4]); // configured station alias from the EEPROM
        d.set_u16(0x0120, al::INIT as u16);
        d.set_u16(0x0130, al::INIT as u16);
        d.set_u16(0x0502, sii_idle);
        d
    }

    /// The EK1100 EtherCAT coupler (no process data).
    pub fn ek1100() -> Device {
        let sii = sii::parse(include_str!("../data/sii-EK1100-full.txt"));
        Device::from_sii("EK1100", sii, 0x11, 8, 8, 0x0040)
    }

    /// The EL1004, 4 digital inputs (one byte at 0x1000).
    pub fn el1004() -> Device {
        let sii = sii::parse(include_str!("../data/sii-EL1004.txt"));
        Device::from_sii("EL1004", sii, 0x12, 3, 4, 0x0040)
    }

    /// The EL2004, 4 digital outputs (0x0F00).
    pub fn el2004() -> Device {
        let sii = sii::parse(include_str!("../data/sii-EL2004-full.txt"));
        Device::from_sii("EL2004", sii, 0x12, 3, 4, 0x0040)
    }

    /// The EL2828, 8 digital outputs (0x0F00).
    pub fn el2828() -> Device {
        let sii = sii::parse(include_str!("../data/sii-EL2828-full.txt"));
        Device::from_sii("EL2828", sii, 0x12, 3, 4, 0x0050)
    }

    /// The EL2889, 16 digital outputs (0x0F00, 0x0F01).
    pub fn el2889() -> Device {
        let sii = sii::parse(include_str!("../data/sii-EL2889-full.txt"));
        Device::from_sii("EL2889", sii, 0x12, 3, 4, 0x0040)
    }

    /// The model name.
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// Vendor, product and revision from the EEPROM.
    pub fn identity(&self) -> (u32, u32, u32) {
        sii::identity(&self.sii)
    }

    pub(crate) fn u16_at(&self, a: usize) -> u16 {
        u16::from_le_bytes([self.mem[a], self.mem[a + 1]])
    }

    pub(crate) fn set_u16(&mut self, a: usize, v: u16) {
        self.mem[a..a + 2].copy_from_slice(&v.to_le_bytes());
    }

    fn u32_at(&self, a: usize) -> u32 {
        u32::from_le_bytes([
            self.mem[a],
            self.mem[a + 1],
            self.mem[a + 2],
            self.mem[a + 3],
        ])
    }

    /// The configured station address (0x0010).
    pub fn station_address(&self) -> u16 {
        self.u16_at(0x0010)
    }

    /// The AL state (low nibble of 0x0130).
    pub fn al_state(&self) -> u8 {
        self.mem[0x0130] & 0x0F
    }

    /// Changes the identity in the EEPROM (a wrong terminal plugged in).
    pub fn set_identity(&mut self, vendor: u32, product: u32, revision: u32) {
        for (w, v) in [(0x08, vendor), (0x0A, product), (0x0C, revision)] {
            self.sii[w] = v as u16;
            self.sii[w + 1] = (v >> 16) as u16;
        }
    }

    /// Refuses requests for AL state `state`, answering with `code` in 0x0134 and the error
    /// bit in 0x0130, as a real ESC does.
    pub fn refuse_transition(&mut self, state: u8, code: u16) {
        self.refuse = Some((state, code));
    }

    /// Whether a datagram touching `[ado, ado + len)` finds registers here: FMMUs and
    /// SyncManagers beyond the device's count do not exist (they add nothing to the WKC).
    pub(crate) fn has(&self, ado: usize, len: usize) -> bool {
        let absent = |base: usize, size: usize, count: usize| {
            ado >= base + count * size && ado + len <= base + 16 * size
        };
        !(absent(0x0600, 16, self.fmmus) || absent(0x0800, 8, self.sms))
    }

    /// Reads `out.len()` bytes at `ado` (0 beyond the modelled space).
    pub(crate) fn read(&self, ado: usize, out: &mut [u8], or: bool) {
        for (i, b) in out.iter_mut().enumerate() {
            let v = self.mem.get(ado + i).copied().unwrap_or(0);
            *b = if or { *b | v } else { v };
        }
    }

    /// Writes `data` at `ado`, then lets the ESC react (AL control, EEPROM commands).
    pub(crate) fn write(&mut self, ado: usize, data: &[u8]) {
        let read_only = |a: usize| matches!(a, 0x0000..=0x000F | 0x0110..=0x0111 | 0x0130..=0x0135);
        for (i, &b) in data.iter().enumerate() {
            let a = ado + i;
            if a < SPACE && !read_only(a) {
                self.mem[a] = b;
            }
        }
        let touches = |a: usize| ado <= a && a < ado + data.len();
        if touches(0x0120) {
            self.al_control(self.mem[0x0120]);
        }
        if touches(0x0502) || touches(0x0503) {
            self.eeprom_command();
        }
    }

    fn al_control(&mut self, control: u8) {
        let requested = control & 0x0F;
        if let Some((state, code)) = self.refuse
            && state == requested
        {
            let current = self.al_state();
            self.set_u16(0x0130, (current | 0x10) as u16);
            self.set_u16(0x0134, code);
            return;
        }
        let current = self.al_state();
        // Going up one step at a time, or down to any lower state, as the AL state machine
        // allows; a jump up (INIT to OP) is refused like real ESCs refuse it.
        let order = |s: u8| match s {
            al::INIT => 0,
            al::PRE_OP | al::BOOT => 1,
            al::SAFE_OP => 2,
            al::OP => 3,
            _ => 9,
        };
        if order(requested) == 9 || order(requested) > order(current) + 1 {
            self.set_u16(0x0130, (current | 0x10) as u16);
            self.set_u16(0x0134, al::INVALID_STATE_CHANGE);
            return;
        }
        // Without a microcontroller, AL status follows AL control, error-ack bit included.
        self.set_u16(0x0130, (control & 0x1F) as u16);
        self.set_u16(0x0134, 0);
    }

    fn eeprom_command(&mut self) {
        let control = self.u16_at(0x0502);
        let address = self.u32_at(0x0504) as usize;
        if control & 0x0100 != 0 {
            // Read: 4 words (8 bytes, as bit 6 of the idle status announces).
            for i in 0..4 {
                let w = self.sii.get(address + i).copied().unwrap_or(0xFFFF);
                self.set_u16(0x0508 + i * 2, w);
            }
        } else if control & 0x0200 != 0 {
            // Write one word (ethercrab's `set_alias_address`).
            if let Some(slot) = self.sii.get_mut(address) {
                *slot = u16::from_le_bytes([self.mem[0x0508], self.mem[0x0509]]);
            }
        }
        self.set_u16(0x0502, self.sii_idle);
    }

    /// Active FMMUs: (logical start, length, physical start, reads, writes).
    pub(crate) fn fmmus(&self) -> impl Iterator<Item = (u32, usize, usize, bool, bool)> + '_ {
        (0..self.fmmus).filter_map(move |i| {
            let b = 0x0600 + i * 16;
            if self.mem[b + 12] & 1 == 0 {
                return None;
            }
            let kind = self.mem[b + 11];
            Some((
                self.u32_at(b),
                self.u16_at(b + 4) as usize,
                self.u16_at(b + 8) as usize,
                kind & 1 != 0,
                kind & 2 != 0,
            ))
        })
    }

    /// The process data area of SyncManagers of `kind` (3 outputs, 4 inputs): start and the
    /// length configured in the SM registers (or the SII length if not configured).
    pub(crate) fn areas(&self, kind: u8) -> Vec<(usize, usize)> {
        self.sync_managers
            .iter()
            .enumerate()
            .filter(|(_, sm)| sm.kind == kind)
            .map(|(i, sm)| {
                let configured = self.u16_at(0x0800 + i * 8 + 2) as usize;
                let len = if configured > 0 {
                    configured
                } else {
                    sm.len.max(1) as usize
                };
                (sm.start as usize, len)
            })
            .collect()
    }
}

/// SyncManagers of the SII's category 41 (0x29), 8 bytes each.
fn sync_managers(sii: &[u16]) -> Vec<SiiSyncManager> {
    let mut at = 0x40;
    while at + 1 < sii.len() && sii[at] != 0xFFFF {
        let (kind, len) = (sii[at], sii[at + 1] as usize);
        if kind == 41 {
            return (0..len / 4)
                .map(|i| {
                    let w = at + 2 + i * 4;
                    SiiSyncManager {
                        start: sii[w],
                        len: sii[w + 1],
                        kind: (sii[w + 3] >> 8) as u8,
                    }
                })
                .collect();
        }
        at += 2 + len;
    }
    Vec::new()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sync_managers_come_from_the_eeprom() {
        assert_eq!(
            Device::el1004().sync_managers,
            [SiiSyncManager {
                start: 0x1000,
                len: 1,
                kind: 4
            }]
        );
        assert_eq!(Device::el2889().sync_managers.len(), 2);
        assert_eq!(Device::el2004().sync_managers[0].len, 0);
        assert!(Device::ek1100().sync_managers.is_empty());
    }

    #[test]
    fn eeprom_reads_deliver_four_words() {
        let mut d = Device::ek1100();
        d.write(0x0502, &[0x00, 0x01, 0x08, 0x00, 0x00, 0x00]);
        let mut out = [0u8; 8];
        d.read(0x0508, &mut out, false);
        assert_eq!(out, [0x02, 0, 0, 0, 0x52, 0x2c, 0x4c, 0x04]); // [A] F111
        assert_eq!(d.u16_at(0x0502), 0x0040);
    }

    #[test]
    fn al_status_follows_control_and_refuses_jumps() {
        let mut d = Device::el2004();
        d.write(0x0120, &[0x11, 0]);
        assert_eq!(d.u16_at(0x0130), 0x0011);
        d.write(0x0120, &[0x02, 0]);
        assert_eq!(d.u16_at(0x0130), 0x0002);
        d.write(0x0120, &[0x08, 0]);
        assert_eq!(d.u16_at(0x0130), 0x0012, "PRE-OP to OP is refused");
        assert_eq!(d.u16_at(0x0134), al::INVALID_STATE_CHANGE);
        d.refuse_transition(al::SAFE_OP, 0x001D);
        d.write(0x0120, &[0x04, 0]);
        assert_eq!((d.al_state(), d.u16_at(0x0134)), (2, 0x001D));
    }
}
