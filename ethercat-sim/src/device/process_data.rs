//! A device's process data: its active FMMUs (logical to physical mapping for LRD, LWR and
//! LRW) and the ESC areas its process-data SyncManagers cover.

use super::Device;
use crate::esc::reg;
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

impl Device {
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
