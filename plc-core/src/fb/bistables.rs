//! The IEC 61131-3 bistables (flip-flops): [`Sr`] (set dominant) and [`Rs`] (reset
//! dominant). They differ only when both inputs are TRUE.

/// SR, the set-dominant flip-flop: `Q1 := S1 OR (NOT R AND Q1)`.
///
/// ```text
/// S1   __/-\_______/------\________
/// R    ______/-\_____/-\_______/-\_
/// Q1   __/---\_____/-----------\___   S1 wins while both are TRUE
/// ```
///
/// ```
/// use plc_core::fb::Sr;
/// let mut alarm = Sr::default();
/// assert!(alarm.call(true, false));
/// assert!(alarm.call(false, false), "kept");
/// assert!(alarm.call(true, true), "set dominates");
/// assert!(!alarm.call(false, true));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "SR", __iec_standard)]
#[allow(non_snake_case)]
pub struct Sr {
    /// Input: set (dominant).
    #[plc(direction = "input")]
    pub S1: bool,
    /// Input: reset.
    #[plc(direction = "input")]
    pub R: bool,
    /// Output (and the state kept between calls).
    #[plc(direction = "output")]
    pub Q1: bool,
}

impl Sr {
    /// Runs the block with `S1 = s1`, `R = r`; returns `Q1`.
    pub fn call(&mut self, s1: bool, r: bool) -> bool {
        self.S1 = s1;
        self.R = r;
        self.Q1 = s1 || (!r && self.Q1);
        self.Q1
    }
}

/// RS, the reset-dominant flip-flop: `Q1 := NOT R1 AND (S OR Q1)`.
///
/// ```text
/// S    __/-\_______/------\________
/// R1   ______/-\_____/-\_______/-\_
/// Q1   __/---\_____/-\_/-------\___   R1 wins while both are TRUE
/// ```
///
/// ```
/// use plc_core::fb::Rs;
/// let mut motor = Rs::default();
/// assert!(motor.call(true, false));
/// assert!(motor.call(false, false), "kept");
/// assert!(!motor.call(true, true), "reset dominates");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "RS", __iec_standard)]
#[allow(non_snake_case)]
pub struct Rs {
    /// Input: set.
    #[plc(direction = "input")]
    pub S: bool,
    /// Input: reset (dominant).
    #[plc(direction = "input")]
    pub R1: bool,
    /// Output (and the state kept between calls).
    #[plc(direction = "output")]
    pub Q1: bool,
}

impl Rs {
    /// Runs the block with `S = s`, `R1 = r1`; returns `Q1`.
    pub fn call(&mut self, s: bool, r1: bool) -> bool {
        self.S = s;
        self.R1 = r1;
        self.Q1 = !r1 && (s || self.Q1);
        self.Q1
    }
}
