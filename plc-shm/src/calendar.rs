//! Times in messages and logs as calendar dates, UTC, without a time-zone database.

/// `2026-12-03 21:14:03 UTC` for nanoseconds since the Unix epoch.
pub fn utc_text(ns: u64) -> String {
    let secs = ns / 1_000_000_000;
    let (days, rest) = (secs / 86_400, secs % 86_400);
    let (y, m, d) = civil_from_days(days as i64);
    format!(
        "{y:04}-{m:02}-{d:02} {:02}:{:02}:{:02} UTC",
        rest / 3600,
        rest / 60 % 60,
        rest % 60
    )
}

/// The proleptic Gregorian date of a day count since 1970-01-01 (the era arithmetic of
/// Howard Hinnant's `civil_from_days`, written out here).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

/// Nanoseconds since the Unix epoch of a UTC time written `2026-12-03 21:14:03` (or with a
/// `T` between date and time, seconds left out, a trailing `Z` or ` UTC`), as
/// [`utc_text`] writes them; `None` for anything else.
pub fn parse_utc(text: &str) -> Option<i64> {
    let t = text.trim();
    let t = t
        .strip_suffix("UTC")
        .or_else(|| t.strip_suffix('Z'))
        .unwrap_or(t)
        .trim_end();
    let (date, time) = t.split_once(['T', ' ']).unwrap_or((t, "00:00"));
    let num = |s: &str, max: u32| s.parse::<u32>().ok().filter(|n| *n <= max);
    let mut d = date.splitn(3, '-');
    let y: i64 = d
        .next()?
        .parse()
        .ok()
        .filter(|y| (1970..=9999).contains(y))?;
    let (m, day) = (num(d.next()?, 12)?, num(d.next()?, 31)?);
    let mut c = time.trim().splitn(3, ':');
    let (h, min) = (num(c.next()?, 23)?, num(c.next()?, 59)?);
    let sec = c.next().map_or(Some(0), |s| num(s, 59))?;
    if m == 0 || day == 0 {
        return None;
    }
    let days = days_from_civil(y, m, day);
    // A day beyond the month's end (02-31) comes back as another date: refused.
    if civil_from_days(days) != (y, m, day) {
        return None;
    }
    let secs = days * 86_400 + i64::from(h * 3600 + min * 60 + sec);
    secs.checked_mul(1_000_000_000)
}

/// The day count since 1970-01-01 of a proleptic Gregorian date (the inverse of
/// `civil_from_days`).
fn days_from_civil(y: i64, m: u32, d: u32) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y.rem_euclid(400);
    let mp = i64::from((m + 9) % 12);
    let doy = (153 * mp + 2) / 5 + i64::from(d) - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn written_utc_times_parse_back_and_impossible_dates_are_refused() {
        for ns in [0u64, 951_782_400, 1_796_332_443, 4_102_444_799] {
            let text = utc_text(ns * 1_000_000_000);
            assert_eq!(parse_utc(&text), Some(ns as i64 * 1_000_000_000), "{text}");
        }
        assert_eq!(
            parse_utc("2026-12-03T21:14Z"),
            Some(1_796_332_440 * 1_000_000_000)
        );
        assert_eq!(parse_utc("2026-12-03"), Some(1_796_256_000 * 1_000_000_000));
        for bad in [
            "2026-02-30",
            "2026-13-01 00:00",
            "1h",
            "",
            "2026-12-03 24:00",
            "x-y-z",
        ] {
            assert_eq!(parse_utc(bad), None, "{bad}");
        }
    }

    #[test]
    fn utc_times_read_as_calendar_dates() {
        assert_eq!(utc_text(0), "1970-01-01 00:00:00 UTC");
        // 2026-12-03 21:14:03 UTC
        assert_eq!(
            utc_text(1_796_332_443 * 1_000_000_000),
            "2026-12-03 21:14:03 UTC"
        );
        assert_eq!(
            utc_text(951_782_400 * 1_000_000_000),
            "2000-02-29 00:00:00 UTC"
        );
    }
}
