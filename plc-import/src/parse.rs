//! Reading a JSON project file: the `variables` object in file order, with every name given
//! twice (also in another case) reported instead of silently overwritten, and syntax errors
//! with line and column; likewise the `types` object, each type's members in its own
//! `variables` object.

use serde::de::{self, DeserializeSeed, MapAccess, Visitor};
use serde_json::Value;
use std::collections::HashSet;
use std::fmt;

/// One structure type of the `types` section: `"Axis": { "description": "..", "variables":
/// { .. } }`.
pub struct TypeDef {
    /// The type's name, as tools show it.
    pub name: String,
    /// The type's fields other than `variables` (its `description`, and unknown ones, which
    /// the checks report).
    pub fields: serde_json::Map<String, Value>,
    /// The members, read as a list's variables are.
    pub members: Parsed,
}

/// The variables of a project file, in file order, and the names given more than once.
pub struct Parsed {
    pub variables: Vec<(String, Value)>,
    /// The second and later uses of a name, with what they declared (checked, not generated).
    pub duplicates: Vec<(String, Value)>,
    /// Whether the file has a `variables` object (a fresh project's file may have none).
    pub has_variables: bool,
    /// The `types` section, in file order (a type name given twice is there twice: the checks
    /// report the second).
    pub types: Vec<TypeDef>,
    /// The names so far in lower case: a set, so a 10,000-variable file is not quadratic.
    seen: HashSet<String>,
}

impl Parsed {
    pub fn new() -> Parsed {
        Parsed {
            variables: Vec::new(),
            duplicates: Vec::new(),
            has_variables: true,
            types: Vec::new(),
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

/// The `types` object: each type's members through [`Variables`], so that a member given twice
/// is reported as a variable given twice is.
struct Types<'a>(&'a mut Vec<TypeDef>);

impl<'de> DeserializeSeed<'de> for Types<'_> {
    type Value = ();
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for Types<'_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an object of types, name: { \"variables\": { ... } }")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        while let Some(name) = map.next_key::<String>()? {
            let mut def = TypeDef {
                name,
                fields: serde_json::Map::new(),
                members: Parsed::new(),
            };
            map.next_value_seed(OneType(&mut def))?;
            self.0.push(def);
        }
        Ok(())
    }
}

/// One type's object.
struct OneType<'a>(&'a mut TypeDef);

impl<'de> DeserializeSeed<'de> for OneType<'_> {
    type Value = ();
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for OneType<'_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a type, { \"variables\": { \"pos\": { \"type\": \"f64\" } } }")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        let mut found = false;
        while let Some(key) = map.next_key::<String>()? {
            if key == "variables" {
                found = true;
                map.next_value_seed(Variables(&mut self.0.members))?;
            } else {
                let value: Value = map.next_value()?;
                self.0.fields.insert(key, value);
            }
        }
        self.0.members.has_variables = found;
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
            } else if key == "types" {
                map.next_value_seed(Types(&mut self.0.types))?;
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
