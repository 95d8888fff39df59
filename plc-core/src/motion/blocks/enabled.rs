//! The Enable-kind blocks: `MC_Power` and `MC_ReadActualPosition`, whose outputs hold while
//! `Enable` is TRUE.

use super::run::Enabled;
use crate::motion::axis::{Axis, AxisState, motion};
use crate::motion::{DriveState, error};

/// MC_Power: powers the axis's drive (the CiA 402 state machine to operation enabled) while
/// `Enable` is TRUE, and off when it is FALSE.
///
/// ```
/// use plc_core::motion::{Axis, McPower};
/// let mut axis = Axis::default();
/// let mut power = McPower::default();
/// power.call(&mut axis, true);
/// assert!(!power.Status, "the drive is not enabled yet");
/// assert!(axis.power);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "MC_Power", __iec_standard)]
#[allow(non_snake_case)]
pub struct McPower {
    /// Input: power on while TRUE.
    #[plc(direction = "input")]
    pub Enable: bool,
    /// Output: the drive is powered and follows the axis's set point.
    #[plc(direction = "output")]
    pub Status: bool,
    /// Output: `Status` is valid (the drive reports a state and no fault).
    #[plc(direction = "output")]
    pub Valid: bool,
    /// Output: the drive faulted.
    #[plc(direction = "output")]
    pub Error: bool,
    /// Output: the drive's error code (0x603F), or why power is refused.
    #[plc(direction = "output")]
    pub ErrorID: u16,
}

impl McPower {
    /// Runs the block for `axis` with `Enable = enable`; returns `Status`.
    pub fn call(&mut self, axis: &mut Axis, enable: bool) -> bool {
        self.Enable = enable;
        axis.power = enable;
        // The power stage's state is reported whether `Enable` is TRUE or not: a drive that
        // faulted while off is still an error.
        let reports = axis.drive.state() != DriveState::NotReadyToSwitchOn;
        let fault = axis.drive.faulted().then_some(axis.drive.error_code);
        let o = Enabled::new(reports, fault);
        (self.Valid, self.Error, self.ErrorID) = (o.valid, o.error, o.error_id);
        self.Status = axis.powered();
        match axis.state() {
            AxisState::Disabled if self.Status => axis.set_state(AxisState::Standstill),
            AxisState::ErrorStop => {}
            _ if !enable || !self.Status => {
                axis.set_state(AxisState::Disabled);
                axis.command = axis.command.wrapping_add(1);
                axis.motion = motion::HOLD;
            }
            _ => {}
        }
        self.Status
    }
}

/// MC_ReadActualPosition: the axis's measured position while `Enable` is TRUE.
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "MC_ReadActualPosition", __iec_standard)]
#[allow(non_snake_case)]
pub struct McReadActualPosition {
    /// Input: reads while TRUE.
    #[plc(direction = "input")]
    pub Enable: bool,
    /// Output: `Position` is valid.
    #[plc(direction = "output")]
    pub Valid: bool,
    /// Output: reading.
    #[plc(direction = "output")]
    pub Busy: bool,
    /// Output: the drive faulted.
    #[plc(direction = "output")]
    pub Error: bool,
    /// Output: why.
    #[plc(direction = "output")]
    pub ErrorID: u16,
    /// Output: the measured position, in user units.
    #[plc(direction = "output")]
    pub Position: f64,
}

impl McReadActualPosition {
    /// Runs the block for `axis`; returns `Position`.
    pub fn call(&mut self, axis: &Axis, enable: bool) -> f64 {
        self.Enable = enable;
        self.Busy = enable;
        let fault = (enable && axis.drive.faulted()).then_some(error::DRIVE_FAULT);
        let o = Enabled::new(enable, fault);
        (self.Valid, self.Error, self.ErrorID) = (o.valid, o.error, o.error_id);
        if self.Valid {
            self.Position = axis.actual_position;
        }
        self.Position
    }
}
