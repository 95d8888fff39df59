//! Distributed clocks in the bus description: a device's `dc = { sync0 = "1ms", shift =
//! "250us" }`, its duration text, and the checks of the whole bus's DC settings.
//!
//! ethercrab configures SYNC0 once per group ([`DcConfig`] is per device only to say which
//! devices take part), so every device with `dc` on one bus must give the same `sync0` and
//! `shift`.

use super::BusConfig;
use crate::time::Time;
use serde::{Deserialize, Serialize};

/// The longest SYNC0 period and shift: ethercrab writes them as 32-bit nanoseconds
/// (about 4.29 s).
pub const MAX_DC_NS: i64 = u32::MAX as i64;

/// A device's distributed clock: SYNC0 pulses every `sync0`, and the MainDevice's process data
/// sent `shift` after each pulse.
///
/// Durations are written as plc-vars reads them everywhere, without or with the IEC prefix:
/// `"1ms"`, `"250us"`, `"T#1ms"`, `"LTIME#2ms500us"`.
///
/// ```
/// use plc_rules::bus::BusConfig;
/// use plc_rules::time::Time;
/// let bus = BusConfig::from_toml_str(r#"
///     [[devices]]
///     name = "outputs"
///     identity = { vendor = 0x2, product = 0x07d43052 }
///     dc = { sync0 = "1ms", shift = "250us" }
/// "#).unwrap();
/// let dc = bus.devices[0].dc.unwrap();
/// assert_eq!((dc.sync0, dc.shift), (Time::from_millis(1), Time::from_micros(250)));
/// assert_eq!(bus.dc(), Some(dc));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DcConfig {
    /// The SYNC0 period: above zero, at most [`MAX_DC_NS`], a whole multiple of the cycle's
    /// period.
    #[serde(with = "duration_text")]
    pub sync0: Time,
    /// When the MainDevice's cycle should reach the SubDevices after each SYNC0 pulse: zero
    /// or more and less than `sync0` (default 0).
    #[serde(default, with = "duration_text", skip_serializing_if = "is_zero_time")]
    pub shift: Time,
}

fn is_zero_time(t: &Time) -> bool {
    *t == Time::ZERO
}

impl BusConfig {
    /// The bus's distributed clock settings: those of its devices with `dc` (validation
    /// checks that they agree), or `None` when no device has `dc`.
    pub fn dc(&self) -> Option<DcConfig> {
        self.devices.iter().find_map(|d| d.dc)
    }
}

/// The problems of the description's `dc` settings, each naming the device and the fix.
pub(super) fn problems(bus: &BusConfig, problems: &mut Vec<String>) {
    let mut first: Option<(usize, &str, DcConfig)> = None;
    for (pos, d) in bus.devices.iter().enumerate() {
        let Some(dc) = d.dc else { continue };
        let at = format!("device {pos} (`{}`), `dc`", d.name);
        let (sync0, shift) = (dc.sync0.as_nanos(), dc.shift.as_nanos());
        if sync0 <= 0 {
            problems.push(format!(
                "{at}: sync0 = \"{}\" is not a period: give one above zero, e.g. \"1ms\"",
                written_duration(dc.sync0)
            ));
        } else if sync0 > MAX_DC_NS {
            problems.push(format!(
                "{at}: sync0 = \"{}\" is longer than the 4.29 s (2^32 - 1 ns) an ESC's SYNC0 \
                 cycle register holds: give a shorter period",
                written_duration(dc.sync0)
            ));
        }
        if shift < 0 {
            problems.push(format!(
                "{at}: shift = \"{}\" is negative: give zero or more, less than sync0",
                written_duration(dc.shift)
            ));
        } else if sync0 > 0 && shift >= sync0 {
            problems.push(format!(
                "{at}: shift = \"{}\" is not less than sync0 = \"{}\": the shift places the \
                 cycle within one SYNC0 period; give a shorter one (e.g. a quarter of sync0)",
                written_duration(dc.shift),
                written_duration(dc.sync0)
            ));
        }
        match first {
            None => first = Some((pos, &d.name, dc)),
            Some((p, name, f)) if f != dc => problems.push(format!(
                "{at}: sync0 = \"{}\", shift = \"{}\" differ from device {p} (`{name}`)'s \
                 sync0 = \"{}\", shift = \"{}\": ethercrab configures one SYNC0 period and shift \
                 per bus, so give every device with `dc` the same",
                written_duration(dc.sync0),
                written_duration(dc.shift),
                written_duration(f.sync0),
                written_duration(f.shift)
            )),
            Some(_) => {}
        }
    }
}

/// A duration as the description writes it (`sync0`, `shift`): the IEC literal without
/// its prefix.
///
/// ```
/// use plc_rules::bus::written_duration;
/// use plc_rules::time::Time;
/// assert_eq!(written_duration(Time::from_micros(250)), "250us");
/// assert_eq!(written_duration(Time::ZERO), "0s");
/// ```
pub fn written_duration(t: Time) -> String {
    let literal = t.to_string();
    match literal.split_once('#') {
        Some((_, rest)) => rest.to_owned(),
        None => literal,
    }
}

/// Durations as text: `"1ms"` or an IEC literal `"T#1ms"` read, `"1ms"` written.
mod duration_text {
    use crate::time::Time;
    use serde::{Deserialize, Deserializer, Serializer};

    pub(super) fn serialize<S: Serializer>(t: &Time, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&super::written_duration(*t))
    }

    pub(super) fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Time, D::Error> {
        let text = String::deserialize(d)?;
        parse(&text).map_err(serde::de::Error::custom)
    }

    /// `1ms`, `-2s`, `T#1ms`, `LTIME#1s500ms`.
    pub(super) fn parse(text: &str) -> Result<Time, String> {
        let t = text.trim();
        let parsed = if t.contains('#') {
            Time::parse(t)
        } else {
            Time::parse(&format!("T#{t}"))
        };
        parsed.map_err(|e| {
            format!("`{text}` is not a duration ({e}): write one such as \"1ms\" or \"250us\"")
        })
    }
}

#[cfg(test)]
mod tests;
