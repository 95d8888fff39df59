//! Bringing a SubDevice back to OP after it dropped out of the cycle, through ethercrab's
//! public register access.
//!
//! ethercrab 0.7 configures SubDevices once, in `init` and `into_op`, and has no call that
//! re-runs one device's configuration. A SubDevice that comes back from a fault is in one of
//! these states, and each needs something different:
//! - still in OP (a pulled and re-plugged cable, no watchdog): nothing;
//! - SAFE-OP with the error bit and AL status code 0x001B (its SyncManager watchdog tripped
//!   while no process data arrived): acknowledge, then request OP;
//! - INIT with station address 0 (it lost power): every register is back at its power-on
//!   value, so give it its station address again (APWR at its ring position), check that its
//!   EEPROM still holds the vendor and product found at start-up (a terminal swapped in is
//!   reported, never given the old one's settings), write back the SyncManagers and FMMUs
//!   ethercrab had configured (read from the device at start-up), and step it through PRE-OP
//!   and SAFE-OP to OP; a device with `dc` gets its clock offset and SYNC0 again in PRE-OP
//!   (`sync0`), before SAFE-OP, where a device that needs SYNC0 checks it.
//!
//! Each attempt sends a few single datagrams per device and never waits for a slow
//! transition: a device with a microcontroller that takes a while to change state is picked
//! up again by the next attempt. The bus description's start-up SDOs are written again in
//! PRE-OP, before SAFE-OP, by the caller's `pre_op` (through ethercrab's CoE, whose mailbox
//! SyncManagers were just restored). A device that cannot be brought back (BOOT, a refused
//! request) stays reported, with its AL status code.

use super::sync0::Sync0Setup;
use ethercrab::error::{Error as CrabError, TimeoutError};
use ethercrab::{AlStatusCode, Command, MainDevice};
use std::time::{Duration, Instant};

/// AL control / status register and its bits (ETG.1000.4).
const AL_CONTROL: u16 = 0x0120;
const AL_STATUS: u16 = 0x0130;
const AL_STATUS_CODE: u16 = 0x0134;
const STATION_ADDRESS: u16 = 0x0010;
const ERROR_ACK: u16 = 0x0010;
const FMMU0: u16 = 0x0600;
const SM0: u16 = 0x0800;

/// Transitions one attempt follows per device before leaving the rest to the next attempt:
/// INIT -> PRE-OP -> SAFE-OP -> OP, plus an acknowledge.
const STEPS_PER_ATTEMPT: usize = 5;

/// The registers ethercrab configured on one SubDevice, read back once it reached OP.
#[derive(Clone, Debug)]
pub(crate) struct Configured {
    /// Ring position.
    pub(crate) position: u16,
    /// Station address ethercrab gave it.
    pub(crate) address: u16,
    /// Its name as ethercrab read it from the EEPROM (the model, e.g. "EL2004").
    pub(crate) model: String,
    /// Vendor and product ethercrab read at start-up, checked again after a restart.
    identity: (u32, u32),
    /// Enabled SyncManagers: register address and the 8 bytes ethercrab wrote.
    sync_managers: Vec<(u16, [u8; 8])>,
    /// Enabled FMMUs: register address and their 16 bytes.
    fmmus: Vec<(u16, [u8; 16])>,
    /// Its clock and SYNC0 settings, on a device configured for SYNC0.
    pub(crate) sync0: Option<Sync0Setup>,
}

impl Configured {
    /// Reads the enabled SyncManagers and FMMUs of the SubDevice at `address`.
    pub(crate) async fn read(
        md: &MainDevice<'_>,
        position: u16,
        address: u16,
        model: &str,
        identity: (u32, u32),
    ) -> Result<Self, CrabError> {
        let fmmu_count: u8 = Command::fprd(address, 0x0004).receive(md).await?;
        let sm_count: u8 = Command::fprd(address, 0x0005).receive(md).await?;
        let mut sync_managers = Vec::new();
        for n in 0..u16::from(sm_count) {
            let reg = SM0 + 8 * n;
            let sm: [u8; 8] = Command::fprd(address, reg).receive(md).await?;
            // Byte 6: activate, bit 0 enable.
            if sm[6] & 1 != 0 {
                sync_managers.push((reg, sm));
            }
        }
        let mut fmmus = Vec::new();
        for n in 0..u16::from(fmmu_count) {
            let reg = FMMU0 + 16 * n;
            let fmmu: [u8; 16] = Command::fprd(address, reg).receive(md).await?;
            // Byte 12: activate, bit 0 enable.
            if fmmu[12] & 1 != 0 {
                fmmus.push((reg, fmmu));
            }
        }
        Ok(Configured {
            position,
            address,
            model: model.to_owned(),
            identity,
            sync_managers,
            fmmus,
            sync0: None,
        })
    }

    /// Writes the SyncManagers and FMMUs back (after a power cycle cleared them).
    async fn restore(&self, md: &MainDevice<'_>) -> Result<(), CrabError> {
        for (reg, sm) in &self.sync_managers {
            let _: [u8; 8] = Command::fpwr(self.address, *reg)
                .send_receive(md, *sm)
                .await?;
        }
        for (reg, fmmu) in &self.fmmus {
            let _: [u8; 16] = Command::fpwr(self.address, *reg)
                .send_receive(md, *fmmu)
                .await?;
        }
        Ok(())
    }
}

/// Where one SubDevice stands after a recovery attempt.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Outcome {
    /// In OP without error.
    Op,
    /// Not in OP yet; the text says what it is and what was done.
    NotOp(String),
    /// No answer at its station address nor at its ring position.
    NoAnswer,
}

/// One attempt to bring the SubDevice `dev` back to OP (see the module documentation).
/// `eeprom_timeout` bounds the EEPROM reads that check a restarted device's identity.
pub(crate) async fn attempt(
    md: &MainDevice<'_>,
    dev: &Configured,
    eeprom_timeout: Duration,
    pre_op: &impl AsyncFn(u16) -> Result<(), String>,
) -> Outcome {
    let mut status = match al_status(md, dev.address).await {
        Ok(s) => s,
        Err(_) => match readdress(md, dev).await {
            Ok(s) => s,
            Err(_) => return Outcome::NoAnswer,
        },
    };
    let mut done = Vec::new();
    let mut last = None;
    for _ in 0..STEPS_PER_ATTEMPT {
        let state = status & 0x000F;
        let error = status & ERROR_ACK != 0;
        let code: Option<AlStatusCode> = if error {
            Command::fprd(dev.address, AL_STATUS_CODE)
                .receive(md)
                .await
                .ok()
                .filter(|c| *c != AlStatusCode::NoError)
        } else {
            None
        };
        // No progress since the last step: a device with a microcontroller takes its time,
        // the next attempt goes on.
        if last == Some((status, code)) {
            break;
        }
        last = Some((status, code));
        let request = match (state, code) {
            (8, None) => return Outcome::Op,
            // Acknowledge in the current state: the device stays there, the error clears.
            (_, Some(code)) => {
                done.push(format!("acknowledged AL status code {code}"));
                state | ERROR_ACK
            }
            (1, None) => {
                // A restarted slot may hold another terminal now: never give it the old
                // one's settings.
                match sii_identity(md, dev.address, eeprom_timeout).await {
                    Ok(found) if found == dev.identity => {}
                    Ok((vendor, product)) => {
                        return Outcome::NotOp(format!(
                            "in INIT after a restart, as another device (vendor {vendor:#x}, product \
                             {product:#010x}; it was vendor {:#x}, product {:#010x}): plc-io does \
                             not configure a replaced device while running: restart the program",
                            dev.identity.0, dev.identity.1
                        ));
                    }
                    Err(_) => break,
                }
                if dev.restore(md).await.is_err() {
                    break;
                }
                done.push("restarted in INIT: wrote its SyncManagers and FMMUs again".into());
                2
            }
            (2, None) => {
                if let Err(e) = pre_op(dev.position).await {
                    return Outcome::NotOp(format!("in PRE-OP: {e}"));
                }
                if let Some(setup) = &dev.sync0 {
                    match restore_sync0(md, dev.address, setup).await {
                        Ok(true) => done.push("configured its clock and SYNC0 again".into()),
                        Ok(false) => {}
                        Err(e) => {
                            return Outcome::NotOp(format!(
                                "in PRE-OP: its SYNC0 could not be configured again ({e}); \
                                 it is tried again at the next attempt: if that keeps \
                                 failing, restart the program"
                            ));
                        }
                    }
                }
                4
            }
            (4, None) => 8,
            _ => {
                return Outcome::NotOp(format!(
                    "in AL state {} ({status:#06x}), which plc-io does not lead back to OP: \
                     restart the program",
                    state_name(state)
                ));
            }
        };
        let written: Result<u16, _> = Command::fpwr(dev.address, AL_CONTROL)
            .send_receive(md, request)
            .await;
        let after = match written {
            Ok(_) => al_status(md, dev.address).await,
            Err(e) => Err(e),
        };
        match after {
            Ok(s) => status = s,
            Err(_) => break,
        }
        // A request (not an acknowledge) answered with the error bit: refused. Report it
        // rather than acknowledging and asking again within this attempt.
        if request & ERROR_ACK == 0 && status & ERROR_ACK != 0 {
            break;
        }
    }
    let state = status & 0x000F;
    if state == 8 && status & ERROR_ACK == 0 {
        return Outcome::Op;
    }
    let mut text = format!("in {}", state_name(state));
    if status & ERROR_ACK != 0 {
        match Command::fprd(dev.address, AL_STATUS_CODE)
            .receive::<AlStatusCode>(md)
            .await
        {
            Ok(code) if code != AlStatusCode::NoError => {
                text.push_str(&format!(", AL status code {code}"))
            }
            _ => text.push_str(" with the error bit set"),
        }
    }
    if !done.is_empty() {
        text.push_str(" (");
        text.push_str(&done.join("; "));
        text.push(')');
    }
    Outcome::NotOp(text)
}

/// A device with `dc` in PRE-OP whose SYNC0 is off (it restarted): its clock and SYNC0
/// configured again (`sync0`); whether that was needed. One whose SYNC0 still runs (it only
/// dropped to PRE-OP) keeps its clock and pulses untouched.
async fn restore_sync0(
    md: &MainDevice<'_>,
    address: u16,
    setup: &Sync0Setup,
) -> Result<bool, CrabError> {
    if Sync0Setup::is_active(md, address).await? {
        return Ok(false);
    }
    setup.restore(md, address).await?;
    Ok(true)
}

/// Vendor and product from SII words 8-11, read through the ESC's EEPROM interface as
/// ethercrab does at start-up (read command, wait while busy, read the data register), each
/// read within `limit` (ethercrab's EEPROM timeout).
async fn sii_identity(
    md: &MainDevice<'_>,
    address: u16,
    limit: Duration,
) -> Result<(u32, u32), CrabError> {
    let word = |b: &[u8]| u32::from_le_bytes([b[0], b[1], b[2], b[3]]);
    let (first, eight) = sii_read(md, address, 0x0008, limit).await?;
    if eight {
        return Ok((word(&first[..4]), word(&first[4..])));
    }
    // An ESC with 4-byte reads: the product is two words further on.
    let (second, _) = sii_read(md, address, 0x000A, limit).await?;
    Ok((word(&first[..4]), word(&second[..4])))
}

/// One EEPROM read at word `at`: the 8 data bytes and whether all 8 are valid (control bit 6).
async fn sii_read(
    md: &MainDevice<'_>,
    address: u16,
    at: u16,
    limit: Duration,
) -> Result<([u8; 8], bool), CrabError> {
    const SII_CONTROL: u16 = 0x0502;
    const SII_DATA: u16 = 0x0508;
    const BUSY: u16 = 0x8000;
    const EIGHT_BYTE_READS: u16 = 0x0040;
    let [lo, hi] = at.to_le_bytes();
    // Read command (bit 8) with the word address.
    Command::fpwr(address, SII_CONTROL)
        .send(md, [0x00u8, 0x01, lo, hi, 0x00, 0x00])
        .await?;
    let started = Instant::now();
    let status = loop {
        let status: u16 = Command::fprd(address, SII_CONTROL).receive(md).await?;
        if status & BUSY == 0 {
            break status;
        }
        if started.elapsed() > limit {
            return Err(CrabError::Timeout(TimeoutError::Eeprom));
        }
    };
    let data: [u8; 8] = Command::fprd(address, SII_DATA).receive(md).await?;
    Ok((data, status & EIGHT_BYTE_READS != 0))
}

async fn al_status(md: &MainDevice<'_>, address: u16) -> Result<u16, CrabError> {
    Command::fprd(address, AL_STATUS).receive(md).await
}

/// The device does not answer at its station address: if it answers at its ring position
/// with another address (0 after a power cycle), give it its address back.
async fn readdress(md: &MainDevice<'_>, dev: &Configured) -> Result<u16, CrabError> {
    // ethercrab's APRD/APWR take the ring position and send its negative as ADP.
    let adp = dev.position;
    let found: u16 = Command::aprd(adp, STATION_ADDRESS).receive(md).await?;
    if found != dev.address {
        let _: u16 = Command::apwr(adp, STATION_ADDRESS)
            .send_receive(md, dev.address)
            .await?;
    }
    al_status(md, dev.address).await
}

fn state_name(state: u16) -> &'static str {
    match state {
        1 => "INIT",
        2 => "PRE-OP",
        3 => "BOOT",
        4 => "SAFE-OP",
        8 => "OP",
        _ => "an unknown state",
    }
}
