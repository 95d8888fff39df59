//! The mailbox of a real SubDevice: its two mailbox SyncManagers, written and read through
//! ethercrab's register access.

use super::mailbox::Mailbox;
use ethercrab::{RegisterAddress, SubDevice, SubDeviceRef};
use plc_rules::bus::sii::{Sii, SmUsage};
use std::time::{Duration, Instant};

/// SyncManager status bit 3: "mailbox full". (A SyncManager's registers, ethercrab's
/// `RegisterAddress::sync_manager(n)`: start u16, length u16, control, status, activate, PDI
/// control.)
const SM_MAILBOX_FULL: u8 = 0x08;

/// Pause between two polls of a SyncManager status.
const POLL: Duration = Duration::from_micros(200);
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
