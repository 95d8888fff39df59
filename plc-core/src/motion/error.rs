//! The `ErrorID`s of the motion blocks. PLCopen leaves the numbers to the implementation; a
//! drive's own fault is reported with the drive's CiA 402 error code (0x603F) by `MC_Power`.

/// A move asked of an axis that is not powered (`MC_Power` first).
pub const NOT_POWERED: u16 = 0x4001;
/// A move asked of an axis in ErrorStop (`MC_Reset` first).
pub const ERROR_STOP: u16 = 0x4002;
/// A move asked while `MC_Stop` holds the axis.
pub const STOPPING: u16 = 0x4003;
/// A velocity, acceleration or deceleration that is not positive and finite, or a position
/// that is not finite.
pub const INVALID_PARAMETER: u16 = 0x4004;
/// The drive faulted (its error code is in the axis's `drive.error_code`).
pub const DRIVE_FAULT: u16 = 0x4005;
/// Homing asked of an axis that is moving.
pub const NOT_AT_STANDSTILL: u16 = 0x4006;
