//! The standard function blocks against IEC 61131-3: its timing diagrams as call sequences,
//! the first-cycle and both-inputs cases, the counters at their presets and at INT's bounds,
//! and property tests against small reference models.

use plc_core::Time;
use plc_core::fb::{Ctd, Ctu, Ctud, FTrig, RTrig, Rs, Sr, Tof, Ton, Tp};
use proptest::prelude::*;

fn ms(n: i64) -> Time {
    Time::from_millis(n)
}

/// Calls a timer at each `(time in ms, IN)` with one `PT`, returning `(Q, ET in ms)` per call.
fn run(
    mut call: impl FnMut(Time, bool, Time) -> (bool, Time),
    pt: i64,
    steps: &[(i64, bool)],
) -> Vec<(bool, i64)> {
    steps
        .iter()
        .map(|&(t, input)| {
            let (q, et) = call(ms(t), input, ms(pt));
            (q, et.as_millis())
        })
        .collect()
}

fn ton(steps: &[(i64, bool)], pt: i64) -> Vec<(bool, i64)> {
    let mut fb = Ton::default();
    run(|n, i, p| (fb.call(n, i, p), fb.ET), pt, steps)
}

fn tof(steps: &[(i64, bool)], pt: i64) -> Vec<(bool, i64)> {
    let mut fb = Tof::default();
    run(|n, i, p| (fb.call(n, i, p), fb.ET), pt, steps)
}

fn tp(steps: &[(i64, bool)], pt: i64) -> Vec<(bool, i64)> {
    let mut fb = Tp::default();
    run(|n, i, p| (fb.call(n, i, p), fb.ET), pt, steps)
}

#[test]
fn ton_delays_a_long_pulse_and_ignores_a_short_one() {
    let steps = [
        (0, true),
        (50, true),
        (100, true),
        (150, true),
        (160, false),
        (200, true),
        (250, true),
        (260, false),
        (400, false),
    ];
    assert_eq!(
        ton(&steps, 100),
        [
            (false, 0),
            (false, 50),
            (true, 100),
            (true, 100), // ET clamped at PT
            (false, 0),
            (false, 0), // a new rising edge starts from zero
            (false, 50),
            (false, 0), // shorter than PT: Q never came
            (false, 0),
        ]
    );
}

#[test]
fn ton_compares_with_the_current_pt() {
    let mut delay = Ton::default();
    assert!(!delay.call(ms(0), true, ms(100)));
    assert!(
        !delay.call(ms(80), true, ms(200)),
        "raised while running: later"
    );
    assert!(!delay.call(ms(150), true, ms(200)));
    assert!(
        delay.call(ms(160), true, ms(120)),
        "lowered below ET: at once"
    );
    assert_eq!(delay.ET, ms(120));
    // Once Q is TRUE, a longer PT does not take it back; ET follows PT.
    assert!(delay.call(ms(170), true, ms(500)));
    assert_eq!(delay.ET, ms(500));
    assert_eq!((delay.IN, delay.PT), (true, ms(500)), "inputs are kept");
}

#[test]
fn ton_with_pt_of_zero_or_below_acts_at_once() {
    for pt in [0, -5] {
        let mut delay = Ton::default();
        assert!(delay.call(ms(10), true, ms(pt)), "PT {pt}");
        assert_eq!(delay.ET, Time::ZERO, "ET never below zero");
        assert!(!delay.call(ms(20), false, ms(pt)));
    }
}

#[test]
fn ton_counts_no_time_when_the_clock_goes_back() {
    let mut delay = Ton::default();
    delay.call(ms(1000), true, ms(100));
    assert!(!delay.call(ms(500), true, ms(100)));
    assert_eq!(delay.ET, Time::ZERO);
    // A span beyond LTIME (MIN to MAX) saturates at its maximum instead of overflowing.
    let mut far = Ton::default();
    assert!(!far.call(Time::MIN, true, Time::MAX));
    assert!(far.call(Time::MAX, true, Time::MAX));
    assert_eq!(far.ET, Time::MAX);
}

#[test]
fn tof_holds_q_for_pt_after_in_falls() {
    let steps = [
        (0, false),
        (10, true),
        (20, false),
        (70, false),
        (80, true), // back before PT: Q stays, ET resets
        (90, false),
        (189, false),
        (190, false),
        (250, false),
        (260, true),
    ];
    assert_eq!(
        tof(&steps, 100),
        [
            (false, 0), // nothing fell on the first call
            (true, 0),
            (true, 0),
            (true, 50),
            (true, 0),
            (true, 0),
            (true, 99),
            (false, 100),
            (false, 100), // ET stays at PT until IN rises
            (true, 0),
        ]
    );
}

#[test]
fn tof_compares_with_the_current_pt_and_zero_acts_at_once() {
    let mut run_on = Tof::default();
    run_on.call(ms(0), true, ms(100));
    assert!(run_on.call(ms(10), false, ms(100)));
    assert!(
        run_on.call(ms(90), false, ms(300)),
        "raised while running: later"
    );
    assert!(
        !run_on.call(ms(100), false, ms(50)),
        "lowered below ET: at once"
    );
    assert_eq!(run_on.ET, ms(50));
    assert!(
        !run_on.call(ms(110), false, ms(1000)),
        "a longer PT does not set Q again"
    );
    for pt in [0, -1] {
        let mut fb = Tof::default();
        assert!(fb.call(ms(0), true, ms(pt)));
        assert!(!fb.call(ms(0), false, ms(pt)), "PT {pt}");
        assert_eq!(fb.ET, Time::ZERO);
    }
}

#[test]
fn tp_gives_pulses_of_pt_that_retriggering_does_not_restart() {
    let steps = [
        (0, true),
        (50, true),
        (100, true), // pulse over, IN still TRUE: ET stays at PT
        (150, false),
        (200, true), // new edge
        (220, false),
        (240, true), // edge during the pulse: ignored
        (300, true), // pulse ends at 200 + PT, not 240 + PT
        (320, false),
        (400, true),
        (420, false),
        (500, false), // ended with IN FALSE: ET resets
    ];
    assert_eq!(
        tp(&steps, 100),
        [
            (true, 0),
            (true, 50),
            (false, 100),
            (false, 0),
            (true, 0),
            (true, 20),
            (true, 40),
            (false, 100),
            (false, 0),
            (true, 0),
            (true, 20),
            (false, 0),
        ]
    );
}

#[test]
fn tp_compares_with_the_current_pt_and_zero_gives_no_pulse() {
    let mut pulse = Tp::default();
    assert!(pulse.call(ms(0), true, ms(100)));
    assert!(
        pulse.call(ms(90), true, ms(200)),
        "lengthened while running"
    );
    assert!(
        !pulse.call(ms(150), true, ms(120)),
        "shortened below ET: ends at once"
    );
    assert_eq!(pulse.ET, ms(120));
    for pt in [0, -10] {
        let mut fb = Tp::default();
        assert!(!fb.call(ms(0), true, ms(pt)), "PT {pt}");
        assert!(!fb.call(ms(10), true, ms(pt)));
    }
}

#[test]
fn r_trig_on_the_first_cycle_sees_an_edge_f_trig_does_not() {
    let mut rising = RTrig::default();
    assert!(
        rising.call(true),
        "CLK TRUE at the first call is a rising edge"
    );
    assert!(!rising.call(true));
    let mut quiet = RTrig::default();
    assert!(!quiet.call(false));
    let mut falling = FTrig::default();
    assert!(
        !falling.call(false),
        "CLK FALSE at the first call is no falling edge"
    );
    let mut held = FTrig::default();
    assert!(!held.call(true));
    assert!(held.call(false));
    assert!(!held.call(false));
    assert!((held.CLK, held.Q) == (false, false));
}

#[test]
fn ctu_reaches_pv_resets_and_stops_at_the_top_of_int() {
    let mut c = Ctu::default();
    assert!(!c.call(true, false, 2));
    assert!(!c.call(true, false, 2), "held TRUE counts once");
    assert!(!c.call(false, false, 2));
    assert!(c.call(true, false, 2), "CV = PV");
    assert_eq!(c.CV, 2);
    // R first: an edge with R does not count, nor does CU held through the reset.
    assert!(!c.call(false, true, 2));
    assert!(!c.call(true, true, 2));
    assert_eq!(c.CV, 0);
    assert!(!c.call(true, false, 2));
    assert_eq!(c.CV, 0);
    let mut top = Ctu {
        CV: i16::MAX - 1,
        ..Ctu::default()
    };
    for _ in 0..3 {
        top.call(true, false, i16::MAX);
        top.call(false, false, i16::MAX);
    }
    assert_eq!(top.CV, i16::MAX);
    assert!(top.Q);
    // Q compares with the current PV, also a negative one.
    assert!(Ctu::default().call(false, false, -1));
}

#[test]
fn ctd_loads_pv_reaches_zero_and_stops_at_the_bottom_of_int() {
    let mut c = Ctd::default();
    assert!(c.call(false, false, 2), "a new CTD has CV 0: Q");
    assert!(!c.call(true, true, 2), "LD first: loads, does not count");
    assert_eq!(c.CV, 2);
    assert!(!c.call(false, false, 2));
    assert!(!c.call(true, false, 2));
    c.call(false, false, 2);
    assert!(c.call(true, false, 2));
    assert_eq!(c.CV, 0);
    let mut bottom = Ctd {
        CV: i16::MIN + 1,
        ..Ctd::default()
    };
    for _ in 0..3 {
        bottom.call(true, false, 0);
        bottom.call(false, false, 0);
    }
    assert_eq!(bottom.CV, i16::MIN);
    assert!(bottom.Q);
    let mut low = Ctd::default();
    low.call(false, true, i16::MIN);
    assert_eq!(low.CV, i16::MIN);
}

#[test]
fn ctud_r_before_ld_before_counting_and_edges_together_cancel() {
    let mut c = Ctud::default();
    assert_eq!(c.call(false, false, false, false, 2), (false, true));
    assert_eq!(c.call(true, false, false, false, 2), (false, false));
    assert_eq!(c.CV, 1);
    assert_eq!(c.call(false, false, false, false, 2), (false, false));
    assert_eq!(c.call(true, true, false, false, 2), (false, false));
    assert_eq!(c.CV, 1, "rising edges of CU and CD together cancel");
    assert_eq!(
        c.call(false, false, false, true, 2),
        (true, false),
        "LD loads PV"
    );
    assert_eq!(c.CV, 2);
    assert_eq!(
        c.call(true, false, true, true, 2),
        (false, true),
        "R wins over LD"
    );
    assert_eq!(c.CV, 0);
    // CD's edge alone counts down, below 0.
    c.call(false, false, false, false, 2);
    assert_eq!(c.call(false, true, false, false, 2), (false, true));
    assert_eq!(c.CV, -1);
    let mut top = Ctud {
        CV: i16::MAX,
        ..Ctud::default()
    };
    top.call(true, false, false, false, i16::MAX);
    assert_eq!((top.CV, top.QU), (i16::MAX, true));
    let mut bottom = Ctud {
        CV: i16::MIN,
        ..Ctud::default()
    };
    bottom.call(false, true, false, false, 0);
    assert_eq!((bottom.CV, bottom.QD), (i16::MIN, true));
}

#[test]
fn sr_is_set_dominant_and_rs_reset_dominant() {
    let mut sr = Sr::default();
    assert!(sr.call(true, true), "SR: both TRUE sets");
    assert!(sr.call(false, false));
    assert!(!sr.call(false, true));
    let mut rs = Rs::default();
    assert!(rs.call(true, false));
    assert!(!rs.call(true, true), "RS: both TRUE resets");
    assert!(!rs.call(false, false));
    assert_eq!((rs.S, rs.R1, rs.Q1), (false, false, false));
    assert_eq!((sr.S1, sr.R, sr.Q1), (false, true, false));
}

/// A sequence of calls: the time step before each call (ms), `IN`, and `PT` (ms, zero or
/// below included).
fn timer_steps() -> impl Strategy<Value = Vec<(i64, bool, i64)>> {
    prop::collection::vec((0i64..60, any::<bool>(), -20i64..150), 1..120)
}

proptest! {
    /// TON's Q is TRUE exactly when IN has been TRUE since a rising edge and, at some call
    /// since then, the time held reached that call's PT (CODESYS's compare with the current
    /// PT; Q latches until IN falls).
    #[test]
    fn ton_matches_its_reference_model(steps in timer_steps()) {
        let mut fb = Ton::default();
        let (mut now, mut rose_at, mut was_in, mut q) = (0i64, 0i64, false, false);
        for (dt, input, pt) in steps {
            now += dt;
            if input && !was_in {
                rose_at = now;
            }
            let held = now - rose_at;
            q = input && (q || held >= pt.max(0));
            let et = if !input { 0 } else if q { pt.max(0) } else { held };
            prop_assert_eq!(fb.call(ms(now), input, ms(pt)), q);
            prop_assert_eq!(fb.ET, ms(et));
            prop_assert!(fb.ET <= ms(pt.max(0)));
            was_in = input;
        }
    }

    /// With one PT throughout, TON's Q is "IN held continuously for at least PT".
    #[test]
    fn ton_q_is_in_held_for_pt(steps in timer_steps(), pt in 0i64..150) {
        let mut fb = Ton::default();
        let (mut now, mut held_since) = (0i64, None::<i64>);
        for (dt, input, _) in steps {
            now += dt;
            held_since = if input { held_since.or(Some(now)) } else { None };
            let expected = held_since.is_some_and(|s| now - s >= pt);
            prop_assert_eq!(fb.call(ms(now), input, ms(pt)), expected);
        }
    }

    /// TOF's Q is TRUE while IN is TRUE and after it fell until, at some call, the time since
    /// the fall reached that call's PT.
    #[test]
    fn tof_matches_its_reference_model(steps in timer_steps()) {
        let mut fb = Tof::default();
        let (mut now, mut fell_at, mut was_in, mut q, mut et) = (0i64, 0i64, false, false, 0i64);
        for (dt, input, pt) in steps {
            now += dt;
            if input {
                q = true;
                et = 0;
            } else {
                if was_in {
                    fell_at = now;
                }
                if q {
                    let since = now - fell_at;
                    q = since < pt.max(0);
                    et = since.min(pt.max(0));
                }
            }
            prop_assert_eq!(fb.call(ms(now), input, ms(pt)), q);
            prop_assert_eq!(fb.ET, ms(et));
            was_in = input;
        }
    }

    /// TP's Q is TRUE from a rising edge of IN that comes while no pulse runs until the time
    /// since that edge reaches the current PT; ET stays at the pulse's end while IN is TRUE.
    #[test]
    fn tp_matches_its_reference_model(steps in timer_steps()) {
        let mut fb = Tp::default();
        let (mut now, mut started, mut was_in, mut q, mut et) = (0i64, 0i64, false, false, 0i64);
        for (dt, input, pt) in steps {
            now += dt;
            if !q && input && !was_in {
                started = now;
                q = true;
            }
            if q {
                let since = now - started;
                q = since < pt.max(0);
                et = since.min(pt.max(0));
            }
            if !q && !input {
                et = 0;
            }
            prop_assert_eq!(fb.call(ms(now), input, ms(pt)), q);
            prop_assert_eq!(fb.ET, ms(et));
            if q {
                prop_assert!(now - started < pt, "a pulse never outlasts the current PT");
            }
            was_in = input;
        }
    }

    /// The counters follow a reference count in i32 clamped to INT, never overflowing, with
    /// R and LD precedence and edge counting.
    #[test]
    fn counters_match_a_clamped_reference_and_never_overflow(
        start in prop_oneof![any::<i16>(), (i16::MAX - 4)..=i16::MAX, i16::MIN..=(i16::MIN + 4)],
        steps in prop::collection::vec(
            (any::<bool>(), any::<bool>(), prop::bool::weighted(0.05), prop::bool::weighted(0.05), any::<i16>()),
            1..300,
        ),
    ) {
        let clamp = |v: i32| v.clamp(i32::from(i16::MIN), i32::from(i16::MAX)) as i16;
        let mut ctu = Ctu { CV: start, ..Ctu::default() };
        let mut ctd = Ctd { CV: start, ..Ctd::default() };
        let mut ctud = Ctud { CV: start, ..Ctud::default() };
        let (mut up_cv, mut down_cv, mut updown_cv) = (start, start, start);
        let (mut cu_was, mut cd_was) = (false, false);
        for (cu, cd, r, ld, pv) in steps {
            let (up, down) = (cu && !cu_was, cd && !cd_was);
            (cu_was, cd_was) = (cu, cd);
            up_cv = if r { 0 } else if up { clamp(i32::from(up_cv) + 1) } else { up_cv };
            down_cv = if ld { pv } else if down { clamp(i32::from(down_cv) - 1) } else { down_cv };
            updown_cv = if r {
                0
            } else if ld {
                pv
            } else {
                clamp(i32::from(updown_cv) + i32::from(up) - i32::from(down))
            };
            prop_assert_eq!(ctu.call(cu, r, pv), up_cv >= pv);
            prop_assert_eq!(ctu.CV, up_cv);
            prop_assert_eq!(ctd.call(cd, ld, pv), down_cv <= 0);
            prop_assert_eq!(ctd.CV, down_cv);
            prop_assert_eq!(ctud.call(cu, cd, r, ld, pv), (updown_cv >= pv, updown_cv <= 0));
            prop_assert_eq!(ctud.CV, updown_cv);
        }
    }
}
