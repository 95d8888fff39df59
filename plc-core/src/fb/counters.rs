//! The IEC 61131-3 counters of `INT` (`i16`): up [`Ctu`], down [`Ctd`] and up-down [`Ctud`].
//!
//! Counting inputs (`CU`, `CD`) count their rising edges (IEC 61131-3 declares them
//! `R_EDGE`): a `CU` held TRUE counts once. The edge memory is updated on every call, whatever
//! `R` and `LD` do, so an input held TRUE through a reset does not count when the reset ends.
//! As with [`RTrig`](super::RTrig), a counting input already TRUE on the first call is an
//! edge. `CV` stops at the bounds of `INT` instead of overflowing: IEC 61131-3 counts up only
//! while `CV < PVmax` (32767) and down only while `CV > PVmin` (-32768).

/// CTU, the up counter: counts rising edges of `CU`; `Q` when `CV >= PV`; `R` resets `CV`.
///
/// ```text
/// CU /--\__/--\__/--\__/--\______________/--\__/--\__
/// R  ________________________/--\____________________
/// CV   1  1  2  2  3  3  4  4  0  0  0  0  1  1  2  2
/// Q  ____________/-----------\_______________________
/// ```
///
/// Three characters per call, `PV` = 3.
///
/// ```
/// use plc_core::fb::Ctu;
/// let mut parts = Ctu::default();
/// for _ in 0..3 {
///     parts.call(true, false, 3);
///     parts.call(false, false, 3);
/// }
/// assert!(parts.Q);
/// assert_eq!(parts.CV, 3);
/// assert!(!parts.call(false, true, 3), "R resets");
/// assert_eq!(parts.CV, 0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "CTU", __iec_standard)]
#[allow(non_snake_case)]
pub struct Ctu {
    /// Input: its rising edges count up.
    #[plc(direction = "input")]
    pub CU: bool,
    /// Input: reset, `CV := 0` (before counting).
    #[plc(direction = "input")]
    pub R: bool,
    /// Input: the preset `Q` compares with.
    #[plc(direction = "input")]
    pub PV: i16,
    /// Output: `CV >= PV`.
    #[plc(direction = "output")]
    pub Q: bool,
    /// Output: the count.
    #[plc(direction = "output")]
    pub CV: i16,
    /// State: `CU` of the previous call (its rising edge counts).
    pub M: bool,
}

impl Ctu {
    /// Runs the counter with `CU = cu`, `R = r`, `PV = pv`; returns `Q`.
    ///
    /// IEC 61131-3: `IF R THEN CV := 0; ELSIF CU (rising) AND CV < PVmax THEN CV := CV + 1;
    /// END_IF; Q := CV >= PV;`
    pub fn call(&mut self, cu: bool, r: bool, pv: i16) -> bool {
        self.CU = cu;
        self.R = r;
        self.PV = pv;
        let up = cu && !self.M;
        self.M = cu;
        if r {
            self.CV = 0;
        } else if up {
            self.CV = self.CV.saturating_add(1);
        }
        self.Q = self.CV >= pv;
        self.Q
    }
}

/// CTD, the down counter: counts rising edges of `CD` down; `Q` when `CV <= 0`; `LD` loads
/// `CV := PV`.
///
/// ```text
/// LD ___/--\___________________________________/--\__
/// CD _________/--\__/--\__/--\__/--\__/--\__/--\_____
/// CV   0  3  3  2  2  1  1  0  0 -1 -1 -2 -2 -3  3  3
/// Q  /--\_________________/--------------------\_____
/// ```
///
/// Three characters per call, `PV` = 3. A new CTD starts at `CV` = 0, so `Q` is TRUE until
/// loaded; `CV` counts on below 0.
///
/// ```
/// use plc_core::fb::Ctd;
/// let mut remaining = Ctd::default();
/// assert!(!remaining.call(false, true, 2), "LD loads PV");
/// assert_eq!(remaining.CV, 2);
/// remaining.call(true, false, 2);
/// assert!(!remaining.Q);
/// remaining.call(false, false, 2);
/// assert!(remaining.call(true, false, 2));
/// assert_eq!(remaining.CV, 0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "CTD", __iec_standard)]
#[allow(non_snake_case)]
pub struct Ctd {
    /// Input: its rising edges count down.
    #[plc(direction = "input")]
    pub CD: bool,
    /// Input: load, `CV := PV` (before counting).
    #[plc(direction = "input")]
    pub LD: bool,
    /// Input: the value `LD` loads.
    #[plc(direction = "input")]
    pub PV: i16,
    /// Output: `CV <= 0`.
    #[plc(direction = "output")]
    pub Q: bool,
    /// Output: the count.
    #[plc(direction = "output")]
    pub CV: i16,
    /// State: `CD` of the previous call (its rising edge counts).
    pub M: bool,
}

impl Ctd {
    /// Runs the counter with `CD = cd`, `LD = ld`, `PV = pv`; returns `Q`.
    ///
    /// IEC 61131-3: `IF LD THEN CV := PV; ELSIF CD (rising) AND CV > PVmin THEN CV := CV - 1;
    /// END_IF; Q := CV <= 0;`
    pub fn call(&mut self, cd: bool, ld: bool, pv: i16) -> bool {
        self.CD = cd;
        self.LD = ld;
        self.PV = pv;
        let down = cd && !self.M;
        self.M = cd;
        if ld {
            self.CV = pv;
        } else if down {
            self.CV = self.CV.saturating_sub(1);
        }
        self.Q = self.CV <= 0;
        self.Q
    }
}

/// CTUD, the up-down counter: rising edges of `CU` count up, of `CD` down; `QU` when
/// `CV >= PV`, `QD` when `CV <= 0`. `R` (`CV := 0`) takes precedence over `LD` (`CV := PV`),
/// and both over counting; rising edges of `CU` and `CD` in the same call cancel out.
///
/// ```text
/// CU /--\__/--\__/--\__/--\____________________/--\__/--\_____
/// CD _____________________/--\__/--\__/--\_____/--\___________
/// R  ______________________________________________________/--
/// CV   1  1  2  2  3  3  4  3  3  2  2  1  1  1  1  1  2  2  0
/// QU ____________/--------------\_____________________________
/// QD ______________________________________________________/--
/// ```
///
/// Three characters per call, `PV` = 3. Where edges of `CU` and `CD` come in the same call
/// (the fifth edge of `CU`), they cancel out.
///
/// ```
/// use plc_core::fb::Ctud;
/// let mut buffer = Ctud::default();
/// buffer.call(true, false, false, false, 2);
/// buffer.call(false, false, false, false, 2);
/// assert_eq!(buffer.call(true, false, false, false, 2), (true, false));
/// assert_eq!(buffer.CV, 2);
/// assert_eq!(buffer.call(false, true, false, false, 2), (false, false));
/// assert_eq!(buffer.call(false, false, true, true, 2), (false, true), "R before LD");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "CTUD", __iec_standard)]
#[allow(non_snake_case)]
pub struct Ctud {
    /// Input: its rising edges count up.
    #[plc(direction = "input")]
    pub CU: bool,
    /// Input: its rising edges count down.
    #[plc(direction = "input")]
    pub CD: bool,
    /// Input: reset, `CV := 0` (before `LD` and counting).
    #[plc(direction = "input")]
    pub R: bool,
    /// Input: load, `CV := PV` (before counting).
    #[plc(direction = "input")]
    pub LD: bool,
    /// Input: the preset `QU` compares with and `LD` loads.
    #[plc(direction = "input")]
    pub PV: i16,
    /// Output: `CV >= PV`.
    #[plc(direction = "output")]
    pub QU: bool,
    /// Output: `CV <= 0`.
    #[plc(direction = "output")]
    pub QD: bool,
    /// Output: the count.
    #[plc(direction = "output")]
    pub CV: i16,
    /// State: `CU` of the previous call (its rising edge counts up).
    pub MU: bool,
    /// State: `CD` of the previous call (its rising edge counts down).
    pub MD: bool,
}

impl Ctud {
    /// Runs the counter with `CU = cu`, `CD = cd`, `R = r`, `LD = ld`, `PV = pv`; returns
    /// `(QU, QD)`.
    ///
    /// IEC 61131-3: `IF R THEN CV := 0; ELSIF LD THEN CV := PV; ELSIF NOT (CU AND CD) THEN
    /// IF CU AND CV < PVmax THEN CV := CV + 1; ELSIF CD AND CV > PVmin THEN CV := CV - 1;
    /// END_IF; END_IF; QU := CV >= PV; QD := CV <= 0;` (`CU`, `CD` their rising edges).
    pub fn call(&mut self, cu: bool, cd: bool, r: bool, ld: bool, pv: i16) -> (bool, bool) {
        self.CU = cu;
        self.CD = cd;
        self.R = r;
        self.LD = ld;
        self.PV = pv;
        let up = cu && !self.MU;
        let down = cd && !self.MD;
        self.MU = cu;
        self.MD = cd;
        if r {
            self.CV = 0;
        } else if ld {
            self.CV = pv;
        } else if up && !down {
            self.CV = self.CV.saturating_add(1);
        } else if down && !up {
            self.CV = self.CV.saturating_sub(1);
        }
        self.QU = self.CV >= pv;
        self.QD = self.CV <= 0;
        (self.QU, self.QD)
    }
}
