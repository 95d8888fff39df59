//! The CoE mailbox of a device with a microcontroller: the mailbox SyncManagers, a request
//! served by the object dictionary as soon as it is written, the reply read back (a reply
//! in fragments one fragment at a time, the next as soon as the MainDevice has read the
//! previous one), and the dictionary's values.

use super::Device;
use crate::coe;
use crate::esc::{SPACE, reg};
use crate::fault::SdoInfoFault;

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

    /// Makes the CoE server misanswer the SDO information service from now on (`None`: answer
    /// it properly again), for tests of a MainDevice that reads object names; see
    /// [`SdoInfoFault`]. Only a device with a CoE mailbox (the EL3004, the AKD) is affected.
    pub fn set_sdo_info_fault(&mut self, fault: Option<SdoInfoFault>) {
        self.sdo_info_fault = fault;
    }

    /// A datagram read `[ado, ado + len)`: reading the last byte of the input mailbox
    /// empties it, and the next fragment of a reply in fragments takes its place.
    pub(super) fn after_mailbox_read(&mut self, ado: usize, len: usize) {
        if let Some((i, start, sm_len)) = self.mailbox_sm(MAILBOX_IN)
            && ado < start + sm_len
            && start + sm_len <= ado + len
            && self.mem[reg::SM0 + 8 * i + 5] & SM_MAILBOX_FULL != 0
        {
            self.mem[reg::SM0 + 8 * i + 5] &= !(SM_MAILBOX_FULL | SM_WRITTEN);
            let counter = self.mem[start + 5] >> 4;
            if let Some(left) = self.endless_fragments {
                // SdoInfoFault::EndlessFragments: another one, whatever the count says.
                self.endless_fragments = Some(left.saturating_sub(1).max(1));
                self.put_reply(&coe::endless_fragment(left), None, counter);
            } else if let Some(next) = self.mailbox_queue.pop_front() {
                self.put_reply(&next, None, counter);
            }
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
    /// request's counter, EMULATOR-NOTES §8; an SDO information reply, or the first of its
    /// fragments, likewise).
    fn on_mailbox_write(&mut self) {
        let (Some((_, out_start, out_len)), Some((_, _, in_len))) =
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
        let body = self.mem[out_start + 6..out_start + 6 + len.min(out_len - 6)].to_vec();
        // A new request: whatever was left of an earlier reply in fragments is dropped.
        self.mailbox_queue.clear();
        self.endless_fragments = None;
        let info =
            body.len() >= 2 && u16::from_le_bytes([body[0], body[1]]) >> 12 == coe::SDO_INFORMATION;
        let fault = self.sdo_info_fault.filter(|_| info);
        let replies = match fault {
            Some(SdoInfoFault::Refused) => vec![coe::refusal()],
            Some(SdoInfoFault::EndlessFragments) => {
                self.endless_fragments = Some(u16::MAX - 1);
                vec![coe::endless_fragment(u16::MAX)]
            }
            Some(SdoInfoFault::Oversized) | None => match self.coe.as_mut() {
                Some(d) => d.serve_mailbox(&body, in_len - 6),
                None => return,
            },
        };
        let mut replies = replies.into_iter();
        let Some(first) = replies.next() else {
            return;
        };
        self.mailbox_queue.extend(replies);
        // SdoInfoFault::Oversized: the header claims the whole mailbox and more.
        let stated = (fault == Some(SdoInfoFault::Oversized)).then_some(in_len as u16);
        self.put_reply(&first, stated, counter);
    }

    /// Puts `reply` (from the CoE header on) into the input mailbox, the header stating
    /// `stated` bytes (the reply's length if `None`), and marks the mailbox full.
    fn put_reply(&mut self, reply: &[u8], stated: Option<u16>, counter: u8) {
        let Some((in_i, in_start, in_len)) = self.mailbox_sm(MAILBOX_IN) else {
            return;
        };
        let reply = &reply[..reply.len().min(in_len - 6)];
        let area = &mut self.mem[in_start..in_start + in_len];
        area.fill(0);
        let len = stated.unwrap_or(reply.len() as u16);
        area[..2].copy_from_slice(&len.to_le_bytes());
        area[5] = MAILBOX_COE | counter << 4;
        area[6..6 + reply.len()].copy_from_slice(reply);
        self.mem[reg::SM0 + 8 * in_i + 5] |= SM_MAILBOX_FULL | SM_WRITTEN;
    }
}
