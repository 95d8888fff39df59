//! A CiA 402 drive's process data (IEC 61800-7-201, the CANopen drive profile that EtherCAT
//! servo drives speak as CoE), its state machine as the statusword reports it, and the
//! controlword commands that move it from state to state.

/// The process data of one CiA 402 drive: what a drive's PDOs carry in cyclic synchronous
/// position (CSP) and velocity (CSV) modes. The member names are the objects' names as a bus
/// scan shows them; physical I/O is declared at the top level of the program (with `link`)
/// and copied into and out of this structure each cycle ([`ENTRIES`] names them).
///
/// ```
/// use plc_core::motion::{Cia402, DriveState};
/// let mut drive = Cia402::default();
/// drive.statusword = 0x0250; // switch on disabled, voltage enabled off, bit 9 remote
/// assert_eq!(drive.state(), DriveState::SwitchOnDisabled);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "CIA402")]
pub struct Cia402 {
    /// 0x6040: the commands to the drive's state machine (written by the program).
    pub controlword: u16,
    /// 0x6041: the drive's state and flags.
    pub statusword: u16,
    /// 0x6060: the mode of operation asked for (8 CSP, 9 CSV, 6 homing).
    pub modes_of_operation: i8,
    /// 0x6061: the mode the drive runs in.
    pub modes_of_operation_display: i8,
    /// 0x607A: the position the drive follows in CSP, in increments.
    pub target_position: i32,
    /// 0x6064: the position measured, in increments.
    pub position_actual_value: i32,
    /// 0x60FF: the velocity the drive follows in CSV, in increments per second.
    pub target_velocity: i32,
    /// 0x606C: the velocity measured, in increments per second.
    pub velocity_actual_value: i32,
    /// 0x60F4: how far the position lags the target, in increments.
    pub following_error_actual_value: i32,
    /// 0x603F: the code of the drive's last fault (CiA 402 error codes; 0 none).
    pub error_code: u16,
}

/// The entries of a drive a [`Cia402`] member is copied from or to: (member, the drive's
/// object index, whether the program writes it). A program links its top-level variables to
/// `ethercat.<device>.<member>` and copies them each cycle.
pub const ENTRIES: [(&str, u16, bool); 10] = [
    ("controlword", 0x6040, true),
    ("statusword", 0x6041, false),
    ("modes_of_operation", 0x6060, true),
    ("modes_of_operation_display", 0x6061, false),
    ("target_position", 0x607A, true),
    ("position_actual_value", 0x6064, false),
    ("target_velocity", 0x60FF, true),
    ("velocity_actual_value", 0x606C, false),
    ("following_error_actual_value", 0x60F4, false),
    ("error_code", 0x603F, false),
];

/// Modes of operation (0x6060).
pub mod mode {
    /// Homing.
    pub const HOMING: i8 = 6;
    /// Cyclic synchronous position.
    pub const CSP: i8 = 8;
    /// Cyclic synchronous velocity.
    pub const CSV: i8 = 9;
}

/// Controlword commands (the state machine's transitions, IEC 61800-7-201 table 30).
pub mod command {
    /// Disable voltage: to switch on disabled.
    pub const DISABLE_VOLTAGE: u16 = 0x0000;
    /// Quick stop: stop with the quick stop deceleration, to switch on disabled.
    pub const QUICK_STOP: u16 = 0x0002;
    /// Shutdown: to ready to switch on.
    pub const SHUTDOWN: u16 = 0x0006;
    /// Switch on (and disable operation): to switched on.
    pub const SWITCH_ON: u16 = 0x0007;
    /// Enable operation: to operation enabled (the drive follows its targets).
    pub const ENABLE_OPERATION: u16 = 0x000F;
    /// Fault reset, on its rising edge: from fault to switch on disabled.
    pub const FAULT_RESET: u16 = 0x0080;
}

/// The states of a CiA 402 drive, as its statusword tells them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DriveState {
    /// Initialising; commands are not taken yet.
    NotReadyToSwitchOn,
    /// Power stage off; the drive waits for Shutdown.
    SwitchOnDisabled,
    /// Waiting for Switch on.
    ReadyToSwitchOn,
    /// Power stage on, not following targets.
    SwitchedOn,
    /// Following targets.
    OperationEnabled,
    /// Stopping with the quick stop deceleration.
    QuickStopActive,
    /// Reacting to a fault.
    FaultReactionActive,
    /// Faulted: needs a fault reset.
    Fault,
}

impl DriveState {
    /// The state a statusword reports (bits 0-3, 5 and 6; IEC 61800-7-201 table 31).
    pub fn of(statusword: u16) -> DriveState {
        match (statusword & 0x4F, statusword & 0x6F) {
            (0x00, _) => DriveState::NotReadyToSwitchOn,
            (0x40, _) => DriveState::SwitchOnDisabled,
            (0x0F, _) => DriveState::FaultReactionActive,
            (0x08, _) => DriveState::Fault,
            (_, 0x21) => DriveState::ReadyToSwitchOn,
            (_, 0x23) => DriveState::SwitchedOn,
            (_, 0x27) => DriveState::OperationEnabled,
            (_, 0x07) => DriveState::QuickStopActive,
            // Any other pattern is none of the states: read it as not ready.
            _ => DriveState::NotReadyToSwitchOn,
        }
    }

    /// The statusword bits a drive in this state reports (bits 0-3, 5, 6; bit 4 voltage
    /// enabled where the power stage is on): what a drive model answers.
    pub fn statusword_bits(self) -> u16 {
        match self {
            DriveState::NotReadyToSwitchOn => 0x0000,
            DriveState::SwitchOnDisabled => 0x0040,
            DriveState::ReadyToSwitchOn => 0x0021,
            DriveState::SwitchedOn => 0x0033,
            DriveState::OperationEnabled => 0x0037,
            DriveState::QuickStopActive => 0x0017,
            DriveState::FaultReactionActive => 0x001F,
            DriveState::Fault => 0x0008,
        }
    }
}

impl Cia402 {
    /// The drive's state.
    pub fn state(&self) -> DriveState {
        DriveState::of(self.statusword)
    }

    /// Whether the drive reports a fault (or is reacting to one).
    pub fn faulted(&self) -> bool {
        matches!(
            self.state(),
            DriveState::Fault | DriveState::FaultReactionActive
        )
    }

    /// The controlword that moves a drive in `state` one step towards operation enabled.
    pub fn towards_enabled(state: DriveState) -> u16 {
        match state {
            DriveState::SwitchOnDisabled | DriveState::QuickStopActive => command::SHUTDOWN,
            DriveState::ReadyToSwitchOn => command::SWITCH_ON,
            DriveState::SwitchedOn | DriveState::OperationEnabled => command::ENABLE_OPERATION,
            DriveState::NotReadyToSwitchOn
            | DriveState::Fault
            | DriveState::FaultReactionActive => command::DISABLE_VOLTAGE,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_state_reads_back_from_the_bits_a_drive_reports() {
        use DriveState::*;
        for s in [
            NotReadyToSwitchOn,
            SwitchOnDisabled,
            ReadyToSwitchOn,
            SwitchedOn,
            OperationEnabled,
            QuickStopActive,
            FaultReactionActive,
            Fault,
        ] {
            // Bits beyond the state's (warning, remote, target reached, ...) do not change it.
            for extra in [0x0000, 0x0080, 0x0200, 0x0400, 0x1000, 0x8000] {
                assert_eq!(DriveState::of(s.statusword_bits() | extra), s, "{s:?}");
            }
        }
    }

    #[test]
    fn the_commands_lead_from_switch_on_disabled_to_operation_enabled() {
        use DriveState::*;
        assert_eq!(Cia402::towards_enabled(SwitchOnDisabled), command::SHUTDOWN);
        assert_eq!(Cia402::towards_enabled(ReadyToSwitchOn), command::SWITCH_ON);
        assert_eq!(
            Cia402::towards_enabled(SwitchedOn),
            command::ENABLE_OPERATION
        );
        assert_eq!(
            Cia402::towards_enabled(OperationEnabled),
            command::ENABLE_OPERATION
        );
    }

    #[test]
    fn the_entries_name_every_member_once() {
        let names: Vec<&str> = ENTRIES.iter().map(|e| e.0).collect();
        let mut unique = names.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), names.len());
        assert_eq!(names.len(), 10);
    }
}
