//! The IEC 61131-3 edge detectors: [`RTrig`] (rising edge) and [`FTrig`] (falling edge).
//!
//! IEC 61131-3 defines both by a memory `M` of the previous `CLK`, initialised so that the
//! first call compares with `CLK` FALSE: an R_TRIG called first with `CLK` TRUE gives `Q`
//! TRUE (a signal already on at start-up is a rising edge), an F_TRIG called first with `CLK`
//! FALSE gives `Q` FALSE (nothing fell). Here `M` holds the previous `CLK` itself in both
//! blocks (IEC 61131-3's F_TRIG keeps its negation, initialised TRUE: the same behaviour), so
//! the all-zero state is the initial one.

/// R_TRIG: `Q` is TRUE for the one call in which `CLK` goes from FALSE to TRUE.
///
/// ```text
/// CLK  __/-----\___/-\/----\_
/// Q    __/\________/\_/\_____   TRUE for one call at each rising edge
/// ```
///
/// On the first call, `CLK` TRUE is a rising edge (IEC 61131-3 starts `M` FALSE).
///
/// ```
/// use plc_core::fb::RTrig;
/// let mut start_button = RTrig::default();
/// assert!(start_button.call(true), "already pressed at the first call: an edge");
/// assert!(!start_button.call(true));
/// assert!(!start_button.call(false));
/// assert!(start_button.call(true));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "R_TRIG", __iec_standard)]
#[allow(non_snake_case)]
pub struct RTrig {
    /// Input: the signal whose rising edges are detected.
    #[plc(direction = "input")]
    pub CLK: bool,
    /// Output: `CLK` rose in this call.
    #[plc(direction = "output")]
    pub Q: bool,
    /// State: `CLK` of the previous call (FALSE before the first).
    pub M: bool,
}

impl RTrig {
    /// Runs the block with `CLK = clk`; returns `Q`.
    pub fn call(&mut self, clk: bool) -> bool {
        self.CLK = clk;
        self.Q = clk && !self.M;
        self.M = clk;
        self.Q
    }
}

/// F_TRIG: `Q` is TRUE for the one call in which `CLK` goes from TRUE to FALSE.
///
/// ```text
/// CLK  __/-----\___/-\/----\_
/// Q    ________/\____/\____/\   TRUE for one call at each falling edge
/// ```
///
/// On the first call nothing has fallen: `Q` is FALSE whatever `CLK` is.
///
/// ```
/// use plc_core::fb::FTrig;
/// let mut door_opened = FTrig::default();
/// assert!(!door_opened.call(false), "FALSE at the first call is no falling edge");
/// assert!(!door_opened.call(true));
/// assert!(door_opened.call(false));
/// assert!(!door_opened.call(false));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "F_TRIG", __iec_standard)]
#[allow(non_snake_case)]
pub struct FTrig {
    /// Input: the signal whose falling edges are detected.
    #[plc(direction = "input")]
    pub CLK: bool,
    /// Output: `CLK` fell in this call.
    #[plc(direction = "output")]
    pub Q: bool,
    /// State: `CLK` of the previous call (FALSE before the first).
    pub M: bool,
}

impl FTrig {
    /// Runs the block with `CLK = clk`; returns `Q`.
    pub fn call(&mut self, clk: bool) -> bool {
        self.CLK = clk;
        self.Q = !clk && self.M;
        self.M = clk;
        self.Q
    }
}
