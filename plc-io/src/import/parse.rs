//! Reading a JSON project file: the `variables` object in file order, with every name given
//! twice (also in another case) reported instead of silently overwritten, and syntax errors
//! with line and column.

use serde::de::{self, DeserializeSeed, MapAccess, Visitor};
use serde_json::Value;
use std::collections::HashSet;
use std::fmt;

/// The variables of a project file, in file order, and the names given more than once.
pub struct Parsed {
    pub variables: Vec<(String, Value)>,
    /// The second and later uses of a name, with what they declared (checked, not generated).
    pub duplicates: Vec<(String, Value)>,
    /// Whether the file has a `variables` object (a fresh project's file may have none).
    pub has_variables: bool,
    /// The names so far in lower case: a set, so a 10,000-variable file is not quadratic.
    seen: HashSet<String>,
}

impl Parsed {
    pub fn new() -> Parsed {
        Parsed {
            variables: Vec::new(),
            duplicates: Vec::new(),
            has_variables: true,
            seen: HashSet::new(),
        }
    }

    /// Adds a variable; a name already given (in any case) goes to `duplicates` instead, and
    /// `false` is returned.
    pub fn push(&mut self, name: String, value: Value) -> bool {
        if self.seen.insert(name.to_ascii_lowercase()) {
            self.variables.push((name, value));
            true
        } else {
            self.duplicates.push((name, value));
            false
        }
    }
}

struct Variables<'a>(&'a mut Parsed);

impl<'de> DeserializeSeed<'de> for Variables<'_> {
    type Value = ();
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for Variables<'_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an object of variables, name: { \"type\": ... }")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        while let Some(name) = map.next_key::<String>()? {
            let value: Value = map.next_value()?;
            self.0.push(name, value);
        }
        Ok(())
    }
}

struct Project<'a>(&'a mut Parsed, &'a mut bool);

impl<'de> Visitor<'de> for Project<'_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON object with a \"variables\" object")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        while let Some(key) = map.next_key::<String>()? {
            if key == "variables" {
                *self.1 = true;
                map.next_value_seed(Variables(self.0))?;
            } else {
                // Other top-level keys of a whole project file are not ours.
                map.next_value::<de::IgnoredAny>()?;
            }
        }
        Ok(())
    }
}

/// Parses `json`; the error text gives line and column of a syntax error.
pub fn parse(json: &str) -> Result<Parsed, String> {
    let mut parsed = Parsed::new();
    let mut found = false;
    let mut de = serde_json::Deserializer::from_str(json);
    de::Deserializer::deserialize_map(&mut de, Project(&mut parsed, &mut found))
        .and_then(|()| de.end())
        .map_err(|e| {
            format!(
                "JSON error at line {}, column {}: {e}",
                e.line(),
                e.column()
            )
        })?;
    // A fresh project's file has no variables yet: an empty struct, with a note.
    parsed.has_variables = found;
    Ok(parsed)
}
