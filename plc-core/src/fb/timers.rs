//! The IEC 61131-3 timers: on-delay [`Ton`], off-delay [`Tof`] and pulse [`Tp`].
//!
//! What the three share, as CODESYS implements them: `PT` is not latched when timing starts;
//! the elapsed time is compared with the `PT` of the current call, every call, so a `PT`
//! changed while a timer runs takes effect at once. A `PT` of zero or below acts at once (a
//! negative `PT` counts as `T#0s`). `ET` never exceeds `PT`. A clock that goes back (a `now`
//! earlier than the timer's start) counts as no time elapsed, never as a negative `ET`.

use crate::Time;

/// `now - start`, never below zero and never overflowing.
fn elapsed(now: Time, start: Time) -> Time {
    now.saturating_sub(start).max(Time::ZERO)
}

/// The preset as the timers use it: a negative `PT` acts as `T#0s`.
fn preset(pt: Time) -> Time {
    pt.max(Time::ZERO)
}

/// TON, the on-delay timer: `Q` becomes TRUE once `IN` has been TRUE for `PT`, and FALSE as
/// soon as `IN` is FALSE.
///
/// ```text
/// IN  __/-------------\___/-\____/-----------\____
/// Q   __________/-----\__________________/---\____
/// ET            ######                   ####       (= PT)
///           ##########               ########
///     ___#############_____#______###########_____
/// ```
///
/// One column per call, `PT` = 8 calls; `ET` drawn as bars (a full bar is `PT`, half a bar
/// `PT / 2`).
///
/// While `IN` is TRUE, `ET` counts from the rising edge of `IN` and `Q` turns TRUE when `ET`
/// reaches the current `PT`; `ET` then stays at `PT` (it follows a `PT` changed later). A
/// pulse of `IN` shorter than `PT` never sets `Q`. `IN` FALSE resets `Q` and `ET`.
/// Raising `PT` before `Q` is TRUE extends the delay; lowering it below `ET` sets `Q` at
/// the next call. Once `Q` is TRUE it stays TRUE until `IN` falls, whatever `PT` becomes.
///
/// ```
/// use plc_core::{Time, fb::Ton};
/// let ms = Time::from_millis;
/// let mut start_delay = Ton::default();
/// assert!(!start_delay.call(ms(0), true, ms(300)));
/// assert!(!start_delay.call(ms(200), true, ms(300)));
/// assert_eq!(start_delay.ET, ms(200));
/// assert!(start_delay.call(ms(300), true, ms(300)));
/// assert!(!start_delay.call(ms(310), false, ms(300)));
/// assert_eq!(start_delay.ET, Time::ZERO);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "TON", __iec_standard)]
#[allow(non_snake_case)]
pub struct Ton {
    /// Input: the timer runs while TRUE.
    #[plc(direction = "input")]
    pub IN: bool,
    /// Input: the delay.
    #[plc(direction = "input")]
    pub PT: Time,
    /// Output: `IN` has been TRUE for `PT`.
    #[plc(direction = "output")]
    pub Q: bool,
    /// Output: the time elapsed since `IN` rose, at most `PT`.
    #[plc(direction = "output")]
    pub ET: Time,
    /// State: `IN` of the previous call (its rising edge starts the timer).
    pub M: bool,
    /// State: the `now` of `IN`'s rising edge.
    pub StartTime: Time,
}

impl Ton {
    /// Runs the timer at time `now` (the cycle's start) with the inputs `IN = input` and
    /// `PT = pt`; returns `Q`.
    pub fn call(&mut self, now: Time, input: bool, pt: Time) -> bool {
        self.IN = input;
        self.PT = pt;
        let pt = preset(pt);
        if input {
            if !self.M {
                self.StartTime = now;
            }
            if self.Q {
                self.ET = pt;
            } else {
                let et = elapsed(now, self.StartTime);
                self.Q = et >= pt;
                self.ET = et.min(pt);
            }
        } else {
            self.Q = false;
            self.ET = Time::ZERO;
        }
        self.M = input;
        self.Q
    }
}

/// TOF, the off-delay timer: `Q` is TRUE while `IN` is TRUE and stays TRUE for `PT` after
/// `IN` falls.
///
/// ```text
/// IN  __/---\_____________/--\__/-\_______________
/// Q   __/-----------\_____/---------------\_______
/// ET                ######                ########  (= PT)
///               ##########            ############
///     _______#############____##___###############
/// ```
///
/// One column per call, `PT` = 8 calls; `ET` drawn as bars (a full bar is `PT`, half a bar
/// `PT / 2`).
///
/// `IN` TRUE sets `Q` and resets `ET`. When `IN` falls, `ET` counts and `Q` turns FALSE when
/// `ET` reaches the current `PT`; `ET` then stays at `PT` until `IN` rises again. `IN`
/// rising before `PT` has passed keeps `Q` TRUE and restarts the delay at the next
/// falling edge. Once `Q` is FALSE a later, longer `PT` does not set it again.
///
/// ```
/// use plc_core::{Time, fb::Tof};
/// let ms = Time::from_millis;
/// let mut fan_run_on = Tof::default();
/// assert!(fan_run_on.call(ms(0), true, ms(1000)));
/// assert!(fan_run_on.call(ms(100), false, ms(1000)));
/// assert!(fan_run_on.call(ms(1099), false, ms(1000)));
/// assert!(!fan_run_on.call(ms(1100), false, ms(1000)));
/// assert_eq!(fan_run_on.ET, ms(1000));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "TOF", __iec_standard)]
#[allow(non_snake_case)]
pub struct Tof {
    /// Input: `Q` follows it on, and goes off `PT` after it.
    #[plc(direction = "input")]
    pub IN: bool,
    /// Input: the delay.
    #[plc(direction = "input")]
    pub PT: Time,
    /// Output: `IN` is TRUE, or fell less than `PT` ago.
    #[plc(direction = "output")]
    pub Q: bool,
    /// Output: the time elapsed since `IN` fell, at most `PT`.
    #[plc(direction = "output")]
    pub ET: Time,
    /// State: `IN` of the previous call (its falling edge starts the timer).
    pub M: bool,
    /// State: the `now` of `IN`'s falling edge.
    pub StartTime: Time,
}

impl Tof {
    /// Runs the timer at time `now` (the cycle's start) with the inputs `IN = input` and
    /// `PT = pt`; returns `Q`.
    pub fn call(&mut self, now: Time, input: bool, pt: Time) -> bool {
        self.IN = input;
        self.PT = pt;
        let pt = preset(pt);
        if input {
            self.Q = true;
            self.ET = Time::ZERO;
        } else {
            if self.M {
                self.StartTime = now;
            }
            if self.Q {
                let et = elapsed(now, self.StartTime);
                self.Q = et < pt;
                self.ET = et.min(pt);
            }
        }
        self.M = input;
        self.Q
    }
}

/// TP, the pulse timer: a rising edge of `IN` makes `Q` TRUE for exactly `PT`, whatever `IN`
/// does meanwhile.
///
/// ```text
/// IN  __/----------\______/\/\/\______/-----------\__
/// Q   __/-------\_________/-------\___/-------\______
/// ET            ###                           ####     (= PT)
///           #######           ####        ########
///     ___##########________#######_____###########___
/// ```
///
/// One column per call, `PT` = 8 calls; `ET` drawn as bars (a full bar is `PT`, half a bar
/// `PT / 2`).
///
/// A rising edge of `IN` while `Q` is FALSE starts a pulse: `Q` TRUE, `ET` counting. The pulse
/// ends when `ET` reaches the current `PT`; edges of `IN` during a pulse are
/// ignored, so a pulse is never restarted or stretched. After the pulse `ET` stays at `PT`
/// while `IN` is TRUE and is reset when `IN` is FALSE. A `PT` of zero or below gives no pulse
/// at all (it ends in the call that starts it).
///
/// ```
/// use plc_core::{Time, fb::Tp};
/// let ms = Time::from_millis;
/// let mut horn = Tp::default();
/// assert!(horn.call(ms(0), true, ms(200)));
/// assert!(horn.call(ms(100), false, ms(200)), "the pulse runs on without IN");
/// assert!(horn.call(ms(150), true, ms(200)), "a new edge does not restart it");
/// assert!(!horn.call(ms(200), true, ms(200)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, plc_derive::PlcStruct)]
#[plc(crate = "crate", name = "TP", __iec_standard)]
#[allow(non_snake_case)]
pub struct Tp {
    /// Input: its rising edge starts a pulse.
    #[plc(direction = "input")]
    pub IN: bool,
    /// Input: the pulse length.
    #[plc(direction = "input")]
    pub PT: Time,
    /// Output: the pulse.
    #[plc(direction = "output")]
    pub Q: bool,
    /// Output: the time since the pulse started, at most `PT`.
    #[plc(direction = "output")]
    pub ET: Time,
    /// State: `IN` of the previous call (its rising edge starts a pulse).
    pub M: bool,
    /// State: the `now` at which the pulse started.
    pub StartTime: Time,
}

impl Tp {
    /// Runs the timer at time `now` (the cycle's start) with the inputs `IN = input` and
    /// `PT = pt`; returns `Q`.
    pub fn call(&mut self, now: Time, input: bool, pt: Time) -> bool {
        self.IN = input;
        self.PT = pt;
        let pt = preset(pt);
        if !self.Q && input && !self.M {
            self.StartTime = now;
            self.Q = true;
        }
        if self.Q {
            let et = elapsed(now, self.StartTime);
            self.Q = et < pt;
            self.ET = et.min(pt);
        }
        if !self.Q && !input {
            self.ET = Time::ZERO;
        }
        self.M = input;
        self.Q
    }
}
