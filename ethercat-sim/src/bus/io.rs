//! The process image as a test sees it: input bytes set on a device, and the outputs a
//! device drives.

use super::SimBus;
use crate::al;

impl SimBus {
    /// Sets input bit `bit` of the device at `pos` (bit 0 = first channel of its first input
    /// SyncManager). Devices without inputs ignore it.
    pub fn set_input_bit(&self, pos: usize, bit: usize, value: bool) {
        self.with(pos, |d| {
            if let Some(area) = d.areas(4).first()
                && bit / 8 < area.len()
            {
                let a = area.start + bit / 8;
                let mask = 1 << (bit % 8);
                d.mem[a] = if value {
                    d.mem[a] | mask
                } else {
                    d.mem[a] & !mask
                };
            }
        })
    }

    /// Sets the input bytes of the device at `pos` (as many as its first input SyncManager
    /// holds).
    pub fn set_inputs(&self, pos: usize, bytes: &[u8]) {
        self.with(pos, |d| {
            if let Some(area) = d.areas(4).first() {
                let n = area.len().min(bytes.len());
                d.mem[area.start..area.start + n].copy_from_slice(&bytes[..n]);
            }
        })
    }

    /// The outputs the device at `pos` drives: its output SyncManagers' bytes in OP, zero in
    /// any other state (the terminals switch their outputs off outside OP).
    pub fn outputs(&self, pos: usize) -> Vec<u8> {
        self.with(pos, |d| {
            let op = d.al_state() == al::OP;
            d.areas(3)
                .iter()
                .flat_map(|area| d.mem[area.clone()].to_vec())
                .map(|b| if op { b } else { 0 })
                .collect()
        })
    }

    /// Output bit `bit` of the device at `pos`.
    pub fn output_bit(&self, pos: usize, bit: usize) -> bool {
        self.outputs(pos)
            .get(bit / 8)
            .is_some_and(|b| b >> (bit % 8) & 1 != 0)
    }
}
