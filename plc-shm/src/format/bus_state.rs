//! The state of the bus, one type from the backend that sees it through the status block to the
//! tools that show it.

use std::fmt;

/// The AL state of the bus as the last exchange saw it, or [`NoBus`](BusState::NoBus) for a
/// program without a bus. Its [`code`](Self::code) is what the status block stores.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum BusState {
    /// The program has no bus (its backend is not a fieldbus).
    NoBus = 0,
    /// Not started, or stopped.
    #[default]
    Stopped = 1,
    /// All SubDevices in INIT.
    Init = 2,
    /// All SubDevices in PRE-OP.
    PreOp = 3,
    /// All SubDevices in SAFE-OP (inputs update, outputs held safe).
    SafeOp = 4,
    /// All SubDevices in OP.
    Op = 5,
    /// SubDevices in different states.
    Mixed = 6,
    /// The last frame did not come back.
    NoAnswer = 7,
}

impl BusState {
    /// Every state, in code order.
    pub const ALL: [BusState; 8] = [
        BusState::NoBus,
        BusState::Stopped,
        BusState::Init,
        BusState::PreOp,
        BusState::SafeOp,
        BusState::Op,
        BusState::Mixed,
        BusState::NoAnswer,
    ];

    /// Upper-case name as EtherCAT tools show it: `OP`, `SAFE-OP`, ... and `NONE` without a bus.
    pub const fn name(self) -> &'static str {
        match self {
            BusState::NoBus => "NONE",
            BusState::Stopped => "STOPPED",
            BusState::Init => "INIT",
            BusState::PreOp => "PRE-OP",
            BusState::SafeOp => "SAFE-OP",
            BusState::Op => "OP",
            BusState::Mixed => "MIXED",
            BusState::NoAnswer => "NO-ANSWER",
        }
    }

    /// The number the status block stores.
    pub const fn code(self) -> u8 {
        self as u8
    }

    /// The state stored as `code`. The status block is written by another process, so a code
    /// this version does not know reads as [`NoBus`](BusState::NoBus) rather than failing.
    pub fn from_code(code: u64) -> BusState {
        usize::try_from(code)
            .ok()
            .and_then(|c| BusState::ALL.get(c).copied())
            .unwrap_or(BusState::NoBus)
    }
}

impl fmt::Display for BusState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::BusState;

    #[test]
    fn every_state_reads_back_from_its_code() {
        for s in BusState::ALL {
            assert_eq!(BusState::from_code(u64::from(s.code())), s, "{s}");
        }
    }

    #[test]
    fn an_unknown_code_reads_as_no_bus() {
        assert_eq!(BusState::from_code(8), BusState::NoBus);
        assert_eq!(BusState::from_code(u64::MAX), BusState::NoBus);
    }

    #[test]
    fn names_pad_to_a_column() {
        assert_eq!(format!("[{:<8}]", BusState::Op), "[OP      ]");
        assert_eq!(BusState::NoBus.to_string(), "NONE");
    }
}
