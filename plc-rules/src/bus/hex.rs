//! Identity numbers in a bus description: TOML has hexadecimal numbers, JSON only strings.

/// A u32 written as a number or as a string `"0x..."`/decimal (JSON lacks hex numbers).
pub(super) mod hex_u32 {
    use serde::{Deserialize, Deserializer, Serializer};

    #[derive(Deserialize)]
    #[serde(untagged)]
    pub(super) enum NumOrText {
        Num(u64),
        Text(String),
    }

    pub(super) fn convert<E: serde::de::Error>(v: NumOrText) -> Result<u32, E> {
        let n = match v {
            NumOrText::Num(n) => n,
            NumOrText::Text(t) => {
                let t = t.trim();
                let parsed = match t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
                    Some(hex) => u64::from_str_radix(&hex.replace('_', ""), 16),
                    None => t.replace('_', "").parse(),
                };
                parsed.map_err(|_| {
                    E::custom(format!(
                        "`{t}` is not a number: write e.g. 2, \"0x044c2c52\" or \"1154\""
                    ))
                })?
            }
        };
        u32::try_from(n).map_err(|_| E::custom(format!("{n} does not fit 32 bits")))
    }

    pub fn serialize<S: Serializer>(v: &u32, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_u32(*v)
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<u32, D::Error> {
        convert(NumOrText::deserialize(d)?)
    }
}

pub(super) mod hex_u32_opt {
    use super::hex_u32::{NumOrText, convert};
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(v: &Option<u32>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(v) => s.serialize_u32(*v),
            None => s.serialize_none(),
        }
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Option<u32>, D::Error> {
        Option::<NumOrText>::deserialize(d)?
            .map(convert)
            .transpose()
    }
}
