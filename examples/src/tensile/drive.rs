//! A CiA 402 drive without a bus, for the program's tests: it takes each command at once and is
//! where it is told to be.

use super::Gm;
use plc_core::motion::{DriveState, command};

/// A CiA 402 drive that takes each command at once and is where it is told to be: the
/// crosshead's drive without a bus.
pub struct Drive {
    state: DriveState,
    position: i32,
    error_code: u16,
    last_controlword: u16,
}

impl Drive {
    /// A drive switched off, at position 0, without a fault.
    pub fn new() -> Drive {
        Drive {
            state: DriveState::SwitchOnDisabled,
            position: 0,
            error_code: 0,
            last_controlword: 0,
        }
    }

    /// Takes the program's outputs and sets its inputs, as an exchange would.
    pub fn exchange(&mut self, gm: &mut Gm) {
        let cw = gm.crosshead_controlword;
        let reset =
            cw & command::FAULT_RESET != 0 && self.last_controlword & command::FAULT_RESET == 0;
        self.last_controlword = cw;
        use DriveState::*;
        self.state = match (self.state, cw & 0x0F) {
            (Fault, _) if reset => {
                self.error_code = 0;
                SwitchOnDisabled
            }
            (Fault, _) => Fault,
            (_, 0x06) => ReadyToSwitchOn,
            (ReadyToSwitchOn | SwitchedOn | OperationEnabled, 0x07) => SwitchedOn,
            (SwitchedOn | OperationEnabled, 0x0F) => OperationEnabled,
            (s, 0x07 | 0x0F) => s,
            _ => SwitchOnDisabled,
        };
        if self.state == OperationEnabled {
            self.position = gm.crosshead_target_position;
        }
        gm.crosshead_statusword = self.state.statusword_bits();
        gm.crosshead_mode_display = gm.crosshead_mode;
        gm.crosshead_position = self.position;
        gm.crosshead_error_code = self.error_code;
    }

    /// Faults the drive with error code `code` (the operator's reset clears it).
    pub fn fault(&mut self, code: u16) {
        self.state = DriveState::Fault;
        self.error_code = code;
    }
}

impl Default for Drive {
    fn default() -> Drive {
        Drive::new()
    }
}
