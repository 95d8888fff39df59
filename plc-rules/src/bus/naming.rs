//! The names a scanned bus description gives its devices and entries, deterministic so that a
//! second scan of the same bus gives the same file:
//!
//! - a device is named by its order number in lower case (`EL1004` -> `el1004`); the second and
//!   later device of one name get `_2`, `_3` ... in ring order (`el1004`, `el1004_2`);
//! - an entry is named by its EEPROM name made an identifier (lower case, every other character
//!   `_`: `"TxPDO State"` -> `txpdo_state`); a name that repeats within a device gets `_1`,
//!   `_2` ... on every occurrence, in PDO order (`"Input"` four times -> `input_1` ..
//!   `input_4`).
//!
//! A name that would start with a digit gets a leading `_`; an empty one is `device` or
//! `entry`. Where a numbered name meets a name the device already has (an entry really named
//! `input_1` beside two `Input`s), the later one gets a further `_2`, `_3` ... until it is
//! unique, so the file always validates.
//!
//! ```
//! use plc_rules::bus::naming::{device_names, entry_names, identifier};
//! assert_eq!(identifier("Status__Underrange"), "status__underrange");
//! assert_eq!(device_names(&["EK1100", "EL1004", "EL1004"]), ["ek1100", "el1004", "el1004_2"]);
//! assert_eq!(entry_names(&["Input", "Input", "Value"]), ["input_1", "input_2", "value"]);
//! ```

use std::collections::{HashMap, HashSet};

/// `text` as an identifier: ASCII letters in lower case, digits and `_` kept, every other
/// character `_`; a leading digit gets a `_` before it. Empty text stays empty.
pub fn identifier(text: &str) -> String {
    let mut out: String = text
        .chars()
        .map(|c| match c {
            'a'..='z' | '0'..='9' | '_' => c,
            'A'..='Z' => c.to_ascii_lowercase(),
            _ => '_',
        })
        .collect();
    if out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, '_');
    }
    out
}

/// Device names for order numbers in ring order: see the module documentation.
pub fn device_names<S: AsRef<str>>(orders: &[S]) -> Vec<String> {
    let bases: Vec<String> = orders.iter().map(|o| base(o.as_ref(), "device")).collect();
    let mut seen: HashMap<&str, usize> = HashMap::new();
    let wanted: Vec<String> = bases
        .iter()
        .map(|b| {
            let n = seen.entry(b).or_insert(0);
            *n += 1;
            if *n == 1 {
                b.clone()
            } else {
                format!("{b}_{n}")
            }
        })
        .collect();
    unique(wanted)
}

/// Entry names for the EEPROM names of one device's entries in PDO order: see the module
/// documentation.
pub fn entry_names<S: AsRef<str>>(names: &[S]) -> Vec<String> {
    let bases: Vec<String> = names.iter().map(|n| base(n.as_ref(), "entry")).collect();
    let mut total: HashMap<&str, usize> = HashMap::new();
    for b in &bases {
        *total.entry(b).or_insert(0) += 1;
    }
    let mut seen: HashMap<&str, usize> = HashMap::new();
    let wanted: Vec<String> = bases
        .iter()
        .map(|b| {
            if total[b.as_str()] == 1 {
                return b.clone();
            }
            let n = seen.entry(b).or_insert(0);
            *n += 1;
            format!("{b}_{n}")
        })
        .collect();
    unique(wanted)
}

fn base(text: &str, empty: &str) -> String {
    let id = identifier(text);
    if id.is_empty() { empty.to_owned() } else { id }
}

/// Makes every name unique: the first holder of a name (in ring or PDO order) keeps it, a
/// later one gets `_2`, `_3` ... until it is unused.
fn unique(wanted: Vec<String>) -> Vec<String> {
    let mut taken: HashSet<String> = HashSet::new();
    let mut out = Vec::with_capacity(wanted.len());
    for name in &wanted {
        let mut candidate = name.clone();
        // At most wanted.len() names are taken, so one of the first wanted.len() + 1
        // suffixes is free: the loop ends.
        let mut n = 1;
        while taken.contains(&candidate) {
            n += 1;
            candidate = format!("{name}_{n}");
        }
        taken.insert(candidate.clone());
        out.push(candidate);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn other_characters_become_underscores_and_letters_lower_case() {
        assert_eq!(identifier("TxPDO Toggle"), "txpdo_toggle");
        assert_eq!(identifier("Limit 1"), "limit_1");
        assert_eq!(identifier("Ch.1 Wert (µV)"), "ch_1_wert___v_");
        assert_eq!(identifier("24V ok"), "_24v_ok");
        assert_eq!(identifier(""), "");
    }

    #[test]
    fn a_repeated_entry_name_is_numbered_on_every_occurrence_in_pdo_order() {
        let names = entry_names(&["Input", "Status", "Input", "Input", "Value"]);
        assert_eq!(names, ["input_1", "status", "input_2", "input_3", "value"]);
    }

    #[test]
    fn repeats_are_found_after_the_names_are_made_identifiers() {
        assert_eq!(
            entry_names(&["Limit 1", "limit_1"]),
            ["limit_1_1", "limit_1_2"]
        );
    }

    #[test]
    fn a_numbered_name_that_meets_a_real_one_gets_a_further_suffix() {
        let names = entry_names(&["Input", "Input", "input_1"]);
        assert_eq!(names, ["input_1", "input_2", "input_1_2"]);
        assert_eq!(names.iter().collect::<HashSet<_>>().len(), 3);
    }

    #[test]
    fn the_second_device_of_a_model_gets_2_and_the_first_keeps_its_name() {
        let names = device_names(&["EK1100", "EL2004", "EL1004", "EL2004", "EL2004"]);
        assert_eq!(
            names,
            ["ek1100", "el2004", "el1004", "el2004_2", "el2004_3"]
        );
    }

    #[test]
    fn a_device_named_like_a_numbered_one_stays_unique() {
        let names = device_names(&["EL2004", "EL2004_2", "EL2004"]);
        assert_eq!(names, ["el2004", "el2004_2", "el2004_2_2"]);
    }

    proptest::proptest! {
        #[test]
        fn any_names_become_unique_identifiers(
            names in proptest::collection::vec("[ -~]{0,6}|Input|input_[12]|[ä1 ]{1,3}", 0..12),
        ) {
            for made in [entry_names(&names), device_names(&names)] {
                proptest::prop_assert_eq!(made.len(), names.len());
                proptest::prop_assert!(made.iter().all(|n| crate::link::is_identifier(n)), "{:?}", made);
                let lower: HashSet<String> = made.iter().map(|n| n.to_ascii_lowercase()).collect();
                proptest::prop_assert_eq!(lower.len(), made.len(), "{:?}", made);
            }
        }
    }

    #[test]
    fn empty_names_fall_back_to_a_word() {
        assert_eq!(device_names(&["", "?"]), ["device", "_"]);
        assert_eq!(entry_names(&["", ""]), ["entry_1", "entry_2"]);
    }
}
