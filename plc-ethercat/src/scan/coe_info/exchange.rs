//! One SDO information request and its answer: the request's mailbox frame (with the
//! exchange's own mailbox counter), then the answer gathered from its fragments, each checked
//! against the mailbox, the protocol and the limits.

use super::mailbox::{Failure, MAX_ANSWER, MAX_FRAGMENTS, Mailbox};

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
pub(super) const GET_OBJECT_REQUEST: u8 = 0x03;
pub(super) const GET_OBJECT_RESPONSE: u8 = 0x04;
pub(super) const GET_ENTRY_REQUEST: u8 = 0x05;
pub(super) const GET_ENTRY_RESPONSE: u8 = 0x06;
const INFO_ERROR: u8 = 0x07;

/// Emergencies a device may put between the fragments of an answer before the answer is
/// given up.
const MAX_EMERGENCIES: usize = 4;
/// The mailbox counter of this exchange: see the module documentation.
#[derive(Debug, Default)]
pub struct Counter(u8);

impl Counter {
    /// The counter for the next request: 0 first, then 1..=7 round.
    pub(super) fn next(&mut self) -> u8 {
        let c = self.0;
        self.0 = if c >= 7 { 1 } else { c + 1 };
        c
    }
}
/// Sends one SDO information request (`opcode`, `data`) and gathers the data of its answer
/// (opcode `expected`) from every fragment.
pub(super) async fn exchange(
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
