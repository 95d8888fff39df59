//! The CiA 402 drive state machine (IEC 61800-7-201 figure 17): the states, the commands a
//! controlword gives, the transitions they cause, and the statusword bits each state shows.

/// A state of the drive's power stage state machine.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) enum State {
    /// After power-on, until the firmware has initialised (left on the first cycle).
    #[default]
    NotReadyToSwitchOn,
    /// Power stage off; waits for Shutdown.
    SwitchOnDisabled,
    /// Waits for Switch on.
    ReadyToSwitchOn,
    /// Power stage on, holding no torque command yet.
    SwitchedOn,
    /// Following the mode's targets.
    OperationEnabled,
    /// Stopping on the quick stop ramp, then to switch on disabled (option code 2).
    QuickStopActive,
    /// Stopping after a fault, then to fault.
    FaultReactionActive,
    /// Power stage off after a fault; waits for a fault reset.
    Fault,
}

/// A controlword's device control command (IEC 61800-7-201 table 30). Bit 7 (fault reset)
/// counts only on its rising edge and only in [`State::Fault`], so it is not decoded here.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Command {
    /// Bit 1 = 0.
    DisableVoltage,
    /// Bits 2, 1 = 0, 1.
    QuickStop,
    /// Bits 2, 1, 0 = 1, 1, 0.
    Shutdown,
    /// Bits 3-0 = 0111 (also "disable operation").
    SwitchOn,
    /// Bits 3-0 = 1111.
    EnableOperation,
}

impl Command {
    /// The command in controlword `cw`, the patterns checked from the strongest bit down as
    /// the standard's table orders them (disable voltage wins over everything).
    pub(crate) fn of(cw: u16) -> Command {
        if cw & 0x0002 == 0 {
            Command::DisableVoltage
        } else if cw & 0x0004 == 0 {
            Command::QuickStop
        } else if cw & 0x0001 == 0 {
            Command::Shutdown
        } else if cw & 0x0008 == 0 {
            Command::SwitchOn
        } else {
            Command::EnableOperation
        }
    }
}

impl State {
    /// The state after controlword `cw` (with `fault_reset` its bit 7's rising edge). The
    /// transitions the drive makes by itself (a fault, the end of a stop) are not here: the
    /// drive applies them where it knows the motor.
    pub(crate) fn on_command(self, cw: u16, fault_reset: bool) -> State {
        use Command as C;
        use State as S;
        let command = Command::of(cw);
        match (self, command) {
            // Transition 1: the firmware is up.
            (S::NotReadyToSwitchOn, _) => S::SwitchOnDisabled,
            // 15: only the edge resets, so a held bit 7 cannot reset a new fault.
            (S::Fault, _) if fault_reset => S::SwitchOnDisabled,
            (S::Fault | S::FaultReactionActive, _) => self,
            // 2
            (S::SwitchOnDisabled, C::Shutdown) => S::ReadyToSwitchOn,
            (S::SwitchOnDisabled, _) => self,
            // 7
            (S::ReadyToSwitchOn, C::DisableVoltage | C::QuickStop) => S::SwitchOnDisabled,
            // 3 (enable operation from here goes through switched on, one cycle each)
            (S::ReadyToSwitchOn, C::SwitchOn | C::EnableOperation) => S::SwitchedOn,
            (S::ReadyToSwitchOn, C::Shutdown) => self,
            // 10, 6, 4
            (S::SwitchedOn, C::DisableVoltage | C::QuickStop) => S::SwitchOnDisabled,
            (S::SwitchedOn, C::Shutdown) => S::ReadyToSwitchOn,
            (S::SwitchedOn, C::EnableOperation) => S::OperationEnabled,
            (S::SwitchedOn, C::SwitchOn) => self,
            // 9, 11, 8, 5
            (S::OperationEnabled, C::DisableVoltage) => S::SwitchOnDisabled,
            (S::OperationEnabled, C::QuickStop) => S::QuickStopActive,
            (S::OperationEnabled, C::Shutdown) => S::ReadyToSwitchOn,
            (S::OperationEnabled, C::SwitchOn) => S::SwitchedOn,
            (S::OperationEnabled, C::EnableOperation) => self,
            // 12 on disable voltage; otherwise the stop runs to its end (option code 2 has
            // no way back to operation enabled).
            (S::QuickStopActive, C::DisableVoltage) => S::SwitchOnDisabled,
            (S::QuickStopActive, _) => self,
        }
    }

    /// Statusword bits 0-6 (IEC 61800-7-201 table 31), as plc-core's `DriveState::
    /// statusword_bits` decodes them: bit 4 "voltage enabled" where the power stage is on,
    /// bit 5 "quick stop" clear while a quick stop runs.
    pub(crate) fn bits(self) -> u16 {
        match self {
            State::NotReadyToSwitchOn => 0x0000,
            State::SwitchOnDisabled => 0x0040,
            State::ReadyToSwitchOn => 0x0021,
            State::SwitchedOn => 0x0033,
            State::OperationEnabled => 0x0037,
            State::QuickStopActive => 0x0017,
            State::FaultReactionActive => 0x001F,
            State::Fault => 0x0008,
        }
    }

    /// Whether the power stage drives the motor (the motor coasts otherwise).
    pub(crate) fn torque(self) -> bool {
        matches!(
            self,
            State::OperationEnabled | State::QuickStopActive | State::FaultReactionActive
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_commands_of_plc_core_lead_to_operation_enabled_and_back() {
        let mut s = State::default().on_command(0, false);
        assert_eq!(s, State::SwitchOnDisabled);
        for (cw, want) in [
            (0x0006, State::ReadyToSwitchOn),
            (0x0007, State::SwitchedOn),
            (0x000F, State::OperationEnabled),
            (0x0007, State::SwitchedOn),
            (0x0006, State::ReadyToSwitchOn),
            (0x0000, State::SwitchOnDisabled),
        ] {
            s = s.on_command(cw, false);
            assert_eq!(s, want, "after {cw:#06x}");
        }
        assert_eq!(
            State::OperationEnabled.on_command(0x0002, false),
            State::QuickStopActive
        );
    }

    #[test]
    fn a_fault_is_left_only_on_a_reset_edge() {
        assert_eq!(State::Fault.on_command(0x0080, false), State::Fault);
        assert_eq!(State::Fault.on_command(0x000F, false), State::Fault);
        assert_eq!(
            State::Fault.on_command(0x0080, true),
            State::SwitchOnDisabled
        );
        assert_eq!(
            State::FaultReactionActive.on_command(0x0080, true),
            State::FaultReactionActive
        );
    }

    #[test]
    fn each_state_shows_its_own_bit_pattern() {
        let states = [
            State::NotReadyToSwitchOn,
            State::SwitchOnDisabled,
            State::ReadyToSwitchOn,
            State::SwitchedOn,
            State::OperationEnabled,
            State::QuickStopActive,
            State::FaultReactionActive,
            State::Fault,
        ];
        let mut bits: Vec<u16> = states.iter().map(|s| s.bits()).collect();
        bits.dedup();
        assert_eq!(bits.len(), states.len());
    }
}
