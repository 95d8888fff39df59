//! One simulated SubDevice: the ESC's address space (registers and process RAM) and what
//! happens when a datagram reads or writes it, and the models of real Beckhoff terminals.

use crate::al;
use crate::coe::{self, Dictionary};
use crate::dc::{self, Position};
use crate::esc::{self, EscInfo, SPACE, reg};
use crate::fault::Faults;
use crate::sii::{self, Completed, Eeprom, SiiSyncManager};
use std::ops::Range;

/// An active FMMU: logical bytes `logical..logical + len` of a datagram map to the ESC's own
/// bytes from `physical` on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Fmmu {
    /// First logical address (register bytes 0-3).
    pub(crate) logical: u32,
    /// Bytes mapped (bytes 4-5).
    pub(crate) len: usize,
    /// First physical address (bytes 8-9).
    pub(crate) physical: usize,
    /// A read FMMU: LRD and LRW take its bytes into the datagram (type byte 11, bit 0).
    pub(crate) reads: bool,
    /// A write FMMU: LWR and LRW store the datagram's bytes (type byte 11, bit 1).
    pub(crate) writes: bool,
}

/// A simulated EtherCAT SubDevice.
///
/// ```
/// use ethercat_sim::Device;
/// let d = Device::el2889();
/// assert_eq!(d.name(), "EL2889");
/// assert_eq!(d.identity(), (2, 0x0B49_3052, 0x0011_0000));
/// ```
#[derive(Clone, Debug)]
pub struct Device {
    name: String,
    esc: EscInfo,
    pub(crate) mem: Vec<u8>,
    eeprom: Eeprom,
    sync_managers: Vec<SiiSyncManager>,
    pub(crate) faults: Faults,
    pub(crate) position: Position,
    /// The CoE object dictionary of a device with a mailbox.
    coe: Option<Dictionary>,
    /// Its contents at power-on (the firmware keeps SDO writes in RAM only).
    coe_at_power_on: Option<Dictionary>,
    /// A terminal with a microcontroller runs the AL state machine in firmware: AL status
    /// does not mirror the acknowledge bit of AL control (EMULATOR-NOTES §5: 0x0001 after
    /// `BWR 0x0120 = 0x0011`).
    microcontroller: bool,
}

/// SII SyncManager kinds of the mailboxes.
const MAILBOX_OUT: u8 = 1;
const MAILBOX_IN: u8 = 2;
/// Mailbox type CoE (low nibble of mailbox header byte 5).
const MAILBOX_COE: u8 = 3;
/// SM status bit 3: mailbox full; bit 0: the last access was a write.
const SM_MAILBOX_FULL: u8 = 0x08;
const SM_WRITTEN: u8 = 0x01;

/// Registers the EEPROM interface computes when read.
const SII_REGS: std::ops::Range<usize> = reg::SII_CONTROL..reg::SII_DATA + 8;

impl Device {
    /// A device from its SII EEPROM words and its ESC's facts. The name is the SII's
    /// order-number string (as ethercrab shows it), or "unknown" if the image has none.
    pub fn from_sii(words: Vec<u16>, esc: EscInfo) -> Device {
        let name = sii::name(&words).unwrap_or_else(|| "unknown".into());
        let mut mem = vec![0; SPACE];
        mem[0x0000] = esc.esc_type;
        mem[0x0001] = esc.revision;
        mem[0x0002..0x0004].copy_from_slice(&esc.build.to_le_bytes());
        mem[0x0004] = esc.fmmus;
        mem[0x0005] = esc.sync_managers;
        mem[0x0006] = esc.ram_kib;
        mem[0x0007] = esc.ports;
        mem[0x0008..0x000A].copy_from_slice(&esc.features.to_le_bytes());
        // Receive-time registers of ports that never latch hold what the real terminals
        // showed in capture [A] (EMULATOR-NOTES §7): "hoff" on port 1, "Verl" on port 3.
        mem[0x0904..0x0908].copy_from_slice(b"hoff");
        mem[0x090C..0x0910].copy_from_slice(b"Verl");
        let mut d = Device {
            name,
            esc,
            mem,
            sync_managers: sii::sync_managers(&words),
            eeprom: Eeprom::new(words, esc.sii_idle),
            faults: Faults::default(),
            position: Position::default(),
            coe: None,
            coe_at_power_on: None,
            microcontroller: false,
        };
        d.load_from_eeprom();
        d.set_u16(reg::AL_CONTROL, al::INIT as u16);
        d.set_u16(reg::AL_STATUS, al::INIT as u16);
        d.set_u16(reg::SII_CONTROL, esc.sii_idle);
        d.set_dl_status();
        d
    }

    /// The EK1100 EtherCAT coupler (no process data). ESC registers from capture \[A\] and a
    /// TwinCAT scan (\[R2\]).
    pub fn ek1100() -> Device {
        let words = sii::parse(include_str!("../data/sii-EK1100-full.txt"));
        Device::from_sii(
            words,
            EscInfo {
                esc_type: 0x11,
                revision: 0x00,
                build: 0x0003,
                fmmus: 8,
                sync_managers: 8,
                ram_kib: 8,
                ports: 0x3B,
                features: 0x00FC,
                dc_system_time: true,
                dl_status_pdi: 0x1,
                sii_idle: 0x0040,
            },
        )
    }

    /// The EL1004, 4 digital inputs (one byte at 0x1000). SII from \[R3\], its strings and
    /// PDO entries completed (TxPDOs 0x1A00-0x1A03, entries 0x60n0:01 "Input"; see
    /// `data/README.md`). ESC registers from \[R2\]; the EEPROM idle status and the missing
    /// system-time unit are taken from the EL2828, which reports the same features (0x01FC).
    pub fn el1004() -> Device {
        let words = sii::parse(include_str!("../data/sii-EL1004.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0050, 0x01FC, false))
    }

    /// The EL2004, 4 digital outputs (0x0F00). Its ESC registers were never captured
    /// except the EEPROM idle status (0x0040, \[D\]); the rest are the EL2889's.
    pub fn el2004() -> Device {
        let words = sii::parse(include_str!("../data/sii-EL2004-full.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0040, 0x00FC, true))
    }

    /// The EL2828, 8 digital outputs (0x0F00). Features, DL status and EEPROM status from
    /// capture \[A\]; it does not count the DC system-time registers there.
    pub fn el2828() -> Device {
        let words = sii::parse(include_str!("../data/sii-EL2828-full.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0050, 0x01FC, false))
    }

    /// The EL2889, 16 digital outputs (0x0F00, 0x0F01). Registers from capture \[A\].
    pub fn el2889() -> Device {
        let words = sii::parse(include_str!("../data/sii-EL2889-full.txt"));
        Device::from_sii(words, Self::terminal_esc(0x0040, 0x00FC, true))
    }

    /// The EL3004, 4 analog inputs ±10 V, with a microcontroller and a CoE mailbox
    /// (EMULATOR-NOTES §8, §10): ethercrab reads its PDO assignment by SDO uploads (1C12 empty,
    /// 1C13 = 1A00/1A02/1A04/1A06) and gets 16 input bytes at 0x1180, per channel a status
    /// word and a 16-bit value. SII from capture \[C\] (words ethercrab never read are 0, or
    /// erased after the SyncManager category: no PDO categories; strings 2-4 completed, see
    /// `data/README.md`); ESC registers as the EL1004's, which reports
    /// the same features (0x01FC) and DL status (0x5613).
    pub fn el3004() -> Device {
        let words = sii::parse(include_str!("../data/sii-EL3004.txt"));
        let mut d = Device::from_sii(words, Self::terminal_esc(0x0050, 0x01FC, false));
        let (vendor, product, revision) = d.identity();
        d.coe = Some(coe::el3004(vendor, product, revision));
        d.coe_at_power_on = d.coe.clone();
        d.microcontroller = true;
        d
    }

    /// The order numbers of the modelled terminals, as [`Device::model`] takes them.
    pub const MODELS: [&'static str; 6] =
        ["EK1100", "EL1004", "EL2004", "EL2828", "EL2889", "EL3004"];

    /// The model of order number `name` (case-insensitive: `"el1004"` is the EL1004), or
    /// `None` for a terminal that is not modelled (see [`Device::MODELS`]).
    ///
    /// ```
    /// use ethercat_sim::Device;
    /// assert_eq!(Device::model("el3004").unwrap().name(), "EL3004");
    /// assert!(Device::model("EL9999").is_none());
    /// ```
    pub fn model(name: &str) -> Option<Device> {
        let make: fn() -> Device = match name.to_ascii_uppercase().as_str() {
            "EK1100" => Device::ek1100,
            "EL1004" => Device::el1004,
            "EL2004" => Device::el2004,
            "EL2828" => Device::el2828,
            "EL2889" => Device::el2889,
            "EL3004" => Device::el3004,
            _ => return None,
        };
        Some(make())
    }

    /// The value of CoE object `index`:`sub` (None without a mailbox or for an unknown
    /// object), e.g. the PDO assignment a MainDevice wrote.
    pub fn sdo(&self, index: u16, sub: u8) -> Option<u32> {
        self.coe.as_ref()?.get(index, sub)
    }

    /// The small ESC of the terminals: 3 FMMUs and 4 SyncManagers (inferred from the reset
    /// working counters of capture \[A\]); type, revision, build, RAM and ports as the EL1004
    /// reported them in \[R2\].
    fn terminal_esc(sii_idle: u16, features: u16, dc_system_time: bool) -> EscInfo {
        EscInfo {
            esc_type: 0x12,
            revision: 0x01,
            build: 0x0001,
            fmmus: 3,
            sync_managers: 4,
            ram_kib: 1,
            ports: 0x4A,
            features,
            dc_system_time,
            dl_status_pdi: 0x3,
            sii_idle,
        }
    }

    /// The model name (the SII's order number, e.g. "EK1100").
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The ESC's facts.
    pub fn esc(&self) -> &EscInfo {
        &self.esc
    }

    /// Vendor, product and revision from the EEPROM.
    pub fn identity(&self) -> (u32, u32, u32) {
        sii::identity(&self.eeprom.words)
    }

    /// The SII EEPROM words (writes by the MainDevice included).
    pub fn sii(&self) -> &[u16] {
        &self.eeprom.words
    }

    /// The SII EEPROM words, to change the image before the device goes on a bus (the ESC
    /// loads the station alias from word 4 at power-up, i.e. in [`Device::from_sii`], and on
    /// a reload command).
    pub fn eeprom_words_mut(&mut self) -> &mut [u16] {
        &mut self.eeprom.words
    }

    /// The SyncManagers the SII describes.
    pub fn sii_sync_managers(&self) -> &[SiiSyncManager] {
        &self.sync_managers
    }

    /// Changes the identity in the EEPROM (a different terminal in this slot).
    pub fn set_identity(&mut self, vendor: u32, product: u32, revision: u32) {
        sii::set_identity(&mut self.eeprom.words, vendor, product, revision);
    }

    /// The configured station address (0x0010).
    pub fn station_address(&self) -> u16 {
        self.u16_at(reg::STATION_ADDRESS)
    }

    /// The AL status register (0x0130): state in bits 0-3, error in bit 4.
    pub fn al_status(&self) -> u16 {
        self.u16_at(reg::AL_STATUS)
    }

    /// The AL state (low nibble of 0x0130).
    pub fn al_state(&self) -> u8 {
        self.mem[reg::AL_STATUS] & 0x0F
    }

    /// The AL status code (0x0134).
    pub fn al_status_code(&self) -> u16 {
        self.u16_at(reg::AL_STATUS_CODE)
    }

    /// Reads registers or process RAM directly, as the device's own PDI would (not a
    /// datagram: no working counter, no side effects; 0 beyond the modelled space).
    pub fn register(&self, address: usize, out: &mut [u8]) {
        for (i, b) in out.iter_mut().enumerate() {
            *b = self.mem.get(address + i).copied().unwrap_or(0);
        }
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

    fn u64_at(&self, a: usize) -> u64 {
        self.u32_at(a) as u64 | (self.u32_at(a + 4) as u64) << 32
    }

    fn set_u64(&mut self, a: usize, v: u64) {
        self.mem[a..a + 8].copy_from_slice(&v.to_le_bytes());
    }

    /// Registers the ESC loads from the EEPROM at power-up and on a reload command.
    fn load_from_eeprom(&mut self) {
        let alias = self.eeprom.words.get(4).copied().unwrap_or(0);
        self.set_u16(reg::STATION_ALIAS, alias);
    }

    /// DL status (0x0110) from the position in the line (EMULATOR-NOTES §6): link and
    /// communication on port 0, and on port 1 unless this is the last device or the link to
    /// the next one is lost (port 1 loop closed); ports 2 and 3 closed. 0x5A31 on a passing EK1100, 0x5613 at the end.
    pub(crate) fn set_dl_status(&mut self) {
        let port1 = self.position.port1_open();
        let low = self.esc.dl_status_pdi as u16 | 0x10 | if port1 { 0x20 } else { 0 };
        let high: u16 = 0x02 | 0x50 | if port1 { 0x08 } else { 0x04 };
        self.set_u16(reg::DL_STATUS, high << 8 | low);
    }

    /// Whether the device answers datagrams addressed to station address `adp`: its
    /// configured address, or its alias when DL control enables alias addressing.
    pub(crate) fn addressed_as(&self, adp: u16) -> bool {
        self.station_address() == adp
            || (self.mem[reg::DL_CONTROL_ALIAS] & 1 != 0 && self.u16_at(reg::STATION_ALIAS) == adp)
    }

    /// Whether a datagram over `[ado, ado + len)` finds registers here.
    pub(crate) fn has(&self, ado: usize, len: usize) -> bool {
        self.esc.has(ado, len)
    }

    /// Brings registers that change by themselves (EEPROM interface, system time) up to date
    /// before a datagram reads `[ado, ado + len)` at bus time `now`.
    fn refresh(&mut self, ado: usize, len: usize, now: u64) {
        let overlaps = |r: std::ops::Range<usize>| ado < r.end && r.start < ado + len;
        if overlaps(SII_REGS) {
            self.tick_eeprom(now);
        }
        if overlaps(reg::DC_SYSTEM_TIME..reg::DC_SYSTEM_TIME + 8) {
            let local = self.position.arrival(now);
            let offset = self.u64_at(reg::DC_SYSTEM_TIME_OFFSET);
            self.set_u64(reg::DC_SYSTEM_TIME, dc::system_time(local, offset));
        }
    }

    fn tick_eeprom(&mut self, now: u64) {
        if let Completed::Data(data) = self.eeprom.tick(now) {
            self.mem[reg::SII_DATA..reg::SII_DATA + 8].copy_from_slice(&data);
        }
        let status = self.eeprom.status();
        self.set_u16(reg::SII_CONTROL, status);
    }

    /// Reads `out.len()` bytes at `ado` into `out` (0 beyond the modelled space).
    pub(crate) fn read(&mut self, ado: usize, out: &mut [u8], now: u64) {
        self.refresh(ado, out.len(), now);
        self.register(ado, out);
        // Reading the last byte of the input mailbox empties it.
        if let Some((i, start, len)) = self.mailbox_sm(MAILBOX_IN)
            && ado < start + len
            && start + len <= ado + out.len()
        {
            self.mem[reg::SM0 + 8 * i + 5] &= !(SM_MAILBOX_FULL | SM_WRITTEN);
        }
    }

    /// The mailbox SyncManager of `kind` if the MainDevice configured and enabled it: its
    /// index, start and length.
    fn mailbox_sm(&self, kind: u8) -> Option<(usize, usize, usize)> {
        self.coe.as_ref()?;
        let i = self.sync_managers.iter().position(|sm| sm.kind == kind)?;
        let r = reg::SM0 + 8 * i;
        let (start, len) = (self.u16_at(r) as usize, self.u16_at(r + 2) as usize);
        (self.mem[r + 6] & 1 != 0 && len >= 16 && start + len <= SPACE).then_some((i, start, len))
    }

    /// The MainDevice wrote the last byte of the output mailbox: the firmware takes the
    /// request at once and puts its answer in the input mailbox (a CoE SDO reply echoing the
    /// request's counter, EMULATOR-NOTES §8).
    fn on_mailbox_write(&mut self) {
        let (Some((_, out_start, _)), Some((in_i, in_start, in_len))) =
            (self.mailbox_sm(MAILBOX_OUT), self.mailbox_sm(MAILBOX_IN))
        else {
            return;
        };
        let header = &self.mem[out_start..out_start + 6];
        let len = u16::from_le_bytes([header[0], header[1]]) as usize;
        let (kind, counter) = (header[5] & 0x0F, header[5] >> 4);
        if kind != MAILBOX_COE {
            return;
        }
        let body = self.mem[out_start + 6..out_start + 6 + len.min(in_len - 6)].to_vec();
        let Some(reply) = self.coe.as_mut().and_then(|d| d.serve(&body, in_len - 6)) else {
            return;
        };
        let area = &mut self.mem[in_start..in_start + in_len];
        area.fill(0);
        area[..2].copy_from_slice(&(reply.len() as u16).to_le_bytes());
        area[5] = MAILBOX_COE | counter << 4;
        area[6..6 + reply.len()].copy_from_slice(&reply);
        self.mem[reg::SM0 + 8 * in_i + 5] |= SM_MAILBOX_FULL | SM_WRITTEN;
    }

    /// ORs the bytes at `ado` into `out` (BRD).
    pub(crate) fn read_or(&mut self, ado: usize, out: &mut [u8], now: u64) {
        self.refresh(ado, out.len(), now);
        for (i, b) in out.iter_mut().enumerate() {
            *b |= self.mem.get(ado + i).copied().unwrap_or(0);
        }
    }

    /// Writes `data` at `ado` at bus time `now`, then lets the ESC react (AL control, EEPROM
    /// commands, DC latches). Read-only bytes keep their value.
    pub(crate) fn write(&mut self, ado: usize, data: &[u8], now: u64) {
        let touches = |a: usize| ado <= a && a < ado + data.len();
        if ado < SII_REGS.end && SII_REGS.start < ado + data.len() {
            // A command that finished in the background finishes before the new bytes land.
            self.tick_eeprom(now);
        }
        let old_system_time = touches(reg::DC_SYSTEM_TIME).then(|| {
            self.refresh(reg::DC_SYSTEM_TIME, 8, now);
            self.u64_at(reg::DC_SYSTEM_TIME)
        });
        for (i, &b) in data.iter().enumerate() {
            let a = ado + i;
            if a < SPACE && esc::writable(a) {
                self.mem[a] = b;
            }
        }
        if reg::RX_ERROR_COUNTERS.start < ado + data.len() && ado < reg::RX_ERROR_COUNTERS.end {
            // A write to any RX error counter clears them all, whatever is written.
            self.mem[reg::RX_ERROR_COUNTERS].fill(0);
        }
        if touches(reg::AL_CONTROL) {
            self.on_al_control();
        }
        if let Some((_, start, len)) = self.mailbox_sm(MAILBOX_OUT)
            && touches(start + len - 1)
        {
            self.on_mailbox_write();
        }
        if touches(reg::SII_CONTROL) || touches(reg::SII_CONTROL + 1) {
            self.on_sii_command(now);
        }
        if touches(reg::DC_RECEIVE_TIME) && self.esc.has_dc() {
            self.on_latch(now);
        }
        if let Some(old) = old_system_time
            && self.esc.dc_system_time
        {
            // System time is not set by a write: the ESC compares and corrects its clock.
            let written = self.u64_at(reg::DC_SYSTEM_TIME);
            self.set_u64(reg::DC_SYSTEM_TIME, old);
            self.on_system_time_write(written, now);
        }
    }

    fn on_al_control(&mut self) {
        let control = self.u16_at(reg::AL_CONTROL);
        let refused = self.faults.refusal((control & 0x0F) as u8);
        let (status, code) =
            al::on_control(self.al_status(), control, refused, self.faults.latched);
        self.faults.latched = (status & al::ERROR != 0 && code != 0).then_some(code);
        let status = if self.microcontroller && code == 0 {
            status & !al::ERROR
        } else {
            status
        };
        self.set_u16(reg::AL_STATUS, status);
        self.set_u16(reg::AL_STATUS_CODE, code);
    }

    /// The device restarts, as after losing its power: every register and the process RAM
    /// back to their power-on values (INIT, station address 0, SyncManagers and FMMUs off,
    /// alias reloaded from the EEPROM, CoE objects back to their defaults), the EEPROM
    /// contents kept. Injected faults stay.
    pub(crate) fn power_on_reset(&mut self) {
        let fresh = Device::from_sii(self.eeprom.words.clone(), self.esc);
        self.mem = fresh.mem;
        self.eeprom = fresh.eeprom;
        self.coe.clone_from(&self.coe_at_power_on);
        self.faults.latched = None;
        self.set_dl_status();
    }

    /// The SyncManager watchdog expired (no process data for longer than its time, e.g. the
    /// MainDevice stopped cycling): a terminal with a microcontroller drops to SAFE-OP,
    /// switches its outputs off, and reports AL status code 0x001B until acknowledged.
    pub(crate) fn trip_watchdog(&mut self) {
        let state = self.al_state().min(al::SAFE_OP) as u16;
        self.set_u16(reg::AL_STATUS, state | al::ERROR);
        self.set_u16(reg::AL_STATUS_CODE, al::SYNC_MANAGER_WATCHDOG);
        self.faults.latched = Some(al::SYNC_MANAGER_WATCHDOG);
    }

    fn on_sii_command(&mut self, now: u64) {
        let control = self.u16_at(reg::SII_CONTROL);
        let address = self.u32_at(reg::SII_ADDRESS);
        let data = self.u16_at(reg::SII_DATA);
        if self.eeprom.command(control, address, data, now) {
            self.load_from_eeprom();
        }
        let status = self.eeprom.status();
        self.set_u16(reg::SII_CONTROL, status);
    }

    fn on_latch(&mut self, now: u64) {
        let (ports, unit) = dc::latch(&self.position, now);
        for (i, time) in ports.iter().enumerate() {
            if let Some(t) = time {
                let a = reg::DC_RECEIVE_TIME + 4 * i;
                self.mem[a..a + 4].copy_from_slice(&t.to_le_bytes());
            }
        }
        if self.esc.dc_system_time {
            self.set_u64(reg::DC_RECEIVE_TIME_PU, unit);
        }
    }

    fn on_system_time_write(&mut self, written: u64, now: u64) {
        let local = self.position.arrival(now);
        let offset = self.u64_at(reg::DC_SYSTEM_TIME_OFFSET);
        let delay = self.u32_at(reg::DC_SYSTEM_TIME_DELAY);
        let (offset, diff) = dc::on_system_time_write(local, offset, delay, written);
        self.set_u64(reg::DC_SYSTEM_TIME_OFFSET, offset);
        self.mem[reg::DC_SYSTEM_TIME_DIFFERENCE..reg::DC_SYSTEM_TIME_DIFFERENCE + 4]
            .copy_from_slice(&diff.to_le_bytes());
    }

    /// The active FMMUs.
    pub(crate) fn fmmus(&self) -> Vec<Fmmu> {
        (0..self.esc.fmmus as usize)
            .filter_map(|i| {
                let b = reg::FMMU0 + i * 16;
                if self.mem[b + 12] & 1 == 0 {
                    return None;
                }
                let kind = self.mem[b + 11];
                Some(Fmmu {
                    logical: self.u32_at(b),
                    len: self.u16_at(b + 4) as usize,
                    physical: self.u16_at(b + 8) as usize,
                    reads: kind & 1 != 0,
                    writes: kind & 2 != 0,
                })
            })
            .collect()
    }

    /// The process data areas (ESC addresses) of SyncManagers of `kind` (3 outputs, 4 inputs),
    /// as long as configured in the SM registers (or the SII's length until configured).
    pub(crate) fn areas(&self, kind: u8) -> Vec<Range<usize>> {
        self.sync_managers
            .iter()
            .enumerate()
            .filter(|(_, sm)| sm.kind == kind)
            .map(|(i, sm)| {
                let configured = self.u16_at(reg::SM0 + i * 8 + 2) as usize;
                let len = if configured > 0 {
                    configured
                } else {
                    sm.len.max(1) as usize
                };
                let start = sm.start as usize;
                start..start + len
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_listed_model_is_found_by_its_name() {
        for name in Device::MODELS {
            assert_eq!(
                Device::model(name).map(|d| d.name().to_owned()).as_deref(),
                Some(name)
            );
        }
    }

    #[test]
    fn models_have_the_real_names_and_identities() {
        let models = [
            (Device::ek1100(), "EK1100", 0x044C_2C52, 0x0012_0000),
            (Device::el1004(), "EL1004", 0x03EC_3052, 0x0013_0000),
            (Device::el2004(), "EL2004", 0x07D4_3052, 0x0010_0000),
            (Device::el2828(), "EL2828", 0x0B0C_3052, 0x0011_0000),
            (Device::el2889(), "EL2889", 0x0B49_3052, 0x0011_0000),
        ];
        for (d, name, product, revision) in models {
            assert_eq!(d.name(), name);
            assert_eq!(d.identity(), (2, product, revision), "{name}");
        }
    }

    #[test]
    fn an_eeprom_read_goes_through_the_registers() {
        let mut d = Device::ek1100();
        d.write(0x0502, &[0x00, 0x01, 0x08, 0x00, 0x00, 0x00], 0);
        let mut status = [0u8; 2];
        d.read(0x0502, &mut status, 1);
        assert_eq!(status, [0x40, 0x81]); // [A] F106
        d.read(0x0502, &mut status, sii::READ_BUSY_NS);
        assert_eq!(status, [0x40, 0x00]);
        let mut out = [0u8; 8];
        d.read(0x0508, &mut out, sii::READ_BUSY_NS);
        assert_eq!(out, [0x02, 0, 0, 0, 0x52, 0x2c, 0x4c, 0x04]); // [A] F112
    }

    #[test]
    fn al_status_follows_control_unless_refused() {
        let mut d = Device::el2004();
        d.write(0x0120, &[0x11, 0], 0);
        assert_eq!(d.al_status(), 0x0011);
        d.write(0x0120, &[0x02, 0], 0);
        assert_eq!(d.al_status(), 0x0002);
        d.faults
            .refuse(al::SAFE_OP, al::INVALID_OUTPUT_CONFIGURATION);
        d.write(0x0120, &[0x04, 0], 0);
        assert_eq!((d.al_status(), d.al_status_code()), (0x0012, 0x001D));
    }

    #[test]
    fn the_alias_comes_from_eeprom_word_4_on_reload() {
        let mut d = Device::ek1100();
        assert_eq!(d.u16_at(reg::STATION_ALIAS), 0);
        d.eeprom.words[4] = 0xABCD;
        assert_eq!(
            d.u16_at(reg::STATION_ALIAS),
            0,
            "only loaded at power-up or reload"
        );
        d.write(0x0502, &[0x00, 0x04], 0);
        assert_eq!(d.u16_at(reg::STATION_ALIAS), 0xABCD);
    }

    #[test]
    fn a_write_to_any_rx_error_counter_clears_them_all() {
        let mut d = Device::el2004();
        d.mem[reg::RX_ERROR_COUNTERS].copy_from_slice(&[1, 2, 3, 4, 5, 6, 7, 8]);
        d.write(0x0305, &[0x55], 0);
        let mut counters = [0xffu8; 8];
        d.read(0x0300, &mut counters, 0);
        assert_eq!(counters, [0; 8]);
    }

    #[test]
    fn a_write_beside_the_rx_error_counters_keeps_them() {
        let mut d = Device::el2004();
        d.mem[reg::RX_ERROR_COUNTERS].copy_from_slice(&[1, 2, 3, 4, 5, 6, 7, 8]);
        d.write(0x0308, &[0], 0);
        d.write(0x02FE, &[0, 0], 0);
        assert_eq!(&d.mem[reg::RX_ERROR_COUNTERS], &[1, 2, 3, 4, 5, 6, 7, 8]);
    }

    #[test]
    fn an_fmmu_reads_back_as_its_fields() {
        let mut d = Device::el2004();
        let mut fmmu = [0u8; 16];
        fmmu[0..4].copy_from_slice(&0x0001_0000u32.to_le_bytes());
        fmmu[4..6].copy_from_slice(&1u16.to_le_bytes());
        fmmu[8..10].copy_from_slice(&0x0f00u16.to_le_bytes());
        fmmu[11] = 2;
        fmmu[12] = 1;
        d.write(reg::FMMU0, &fmmu, 0);
        let expected = Fmmu {
            logical: 0x0001_0000,
            len: 1,
            physical: 0x0f00,
            reads: false,
            writes: true,
        };
        assert_eq!(d.fmmus(), [expected]);
    }
}
