//! The CoE mailbox of a device with a microcontroller: the mailbox SyncManagers, a request
//! served by the object dictionary as soon as it is written, the reply read back, and the
//! dictionary's values.

use super::Device;
use crate::esc::{SPACE, reg};

/// SII SyncManager kinds of the mailboxes.
const MAILBOX_OUT: u8 = 1;
const MAILBOX_IN: u8 = 2;
/// Mailbox type CoE (low nibble of mailbox header byte 5).
const MAILBOX_COE: u8 = 3;
/// SM status bit 3: mailbox full; bit 0: the last access was a write.
const SM_MAILBOX_FULL: u8 = 0x08;
const SM_WRITTEN: u8 = 0x01;

impl Device {
    /// The value of CoE object `index`:`sub` (None without a mailbox or for an unknown
    /// object), e.g. the PDO assignment a MainDevice wrote.
    pub fn sdo(&self, index: u16, sub: u8) -> Option<u32> {
        self.coe.as_ref()?.get(index, sub)
    }

    /// A datagram read `[ado, ado + len)`: reading the last byte of the input mailbox
    /// empties it.
    pub(super) fn after_mailbox_read(&mut self, ado: usize, len: usize) {
        if let Some((i, start, sm_len)) = self.mailbox_sm(MAILBOX_IN)
            && ado < start + sm_len
            && start + sm_len <= ado + len
        {
            self.mem[reg::SM0 + 8 * i + 5] &= !(SM_MAILBOX_FULL | SM_WRITTEN);
        }
    }

    /// A datagram wrote `[ado, ado + len)`: a write of the output mailbox's last byte hands
    /// the request to the firmware.
    pub(super) fn after_mailbox_write(&mut self, ado: usize, len: usize) {
        let touches = |a: usize| ado <= a && a < ado + len;
        if let Some((_, start, sm_len)) = self.mailbox_sm(MAILBOX_OUT)
            && touches(start + sm_len - 1)
        {
            self.on_mailbox_write();
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
}
