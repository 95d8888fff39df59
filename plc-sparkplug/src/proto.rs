//! The Sparkplug B payload (`org.eclipse.tahu.protobuf.Payload` of the specification's
//! `sparkplug_b.proto`, Sparkplug B 3.0), as prost messages with the specification's field
//! numbers and types, so no protoc runs at build time and no wire encoding is written by hand.
//!
//! Left out: DataSet and Template values and the extension fields (this edge node sends none;
//! prost skips them in what it receives, so a command that carries one is refused by datatype).

/// A Sparkplug B payload: every message but STATE.
#[derive(Clone, PartialEq, prost::Message)]
pub struct Payload {
    /// Milliseconds since the Unix epoch (UTC) when the message was sent.
    #[prost(uint64, optional, tag = "1")]
    pub timestamp: Option<u64>,
    /// The metrics.
    #[prost(message, repeated, tag = "2")]
    pub metrics: Vec<Metric>,
    /// The node's message sequence number, 0 to 255 (none in an NDEATH).
    #[prost(uint64, optional, tag = "3")]
    pub seq: Option<u64>,
    /// Optional UUID of the payload's schema.
    #[prost(string, optional, tag = "4")]
    pub uuid: Option<String>,
    /// Optional opaque body.
    #[prost(bytes = "vec", optional, tag = "5")]
    pub body: Option<Vec<u8>>,
}

/// One metric of a payload.
#[derive(Clone, PartialEq, prost::Message)]
pub struct Metric {
    /// The name (in births; data and commands may give only the alias).
    #[prost(string, optional, tag = "1")]
    pub name: Option<String>,
    /// The alias the birth gave it.
    #[prost(uint64, optional, tag = "2")]
    pub alias: Option<u64>,
    /// Milliseconds since the Unix epoch (UTC) of the value.
    #[prost(uint64, optional, tag = "3")]
    pub timestamp: Option<u64>,
    /// The datatype ([`DataType`](crate::metric::DataType) as a number).
    #[prost(uint32, optional, tag = "4")]
    pub datatype: Option<u32>,
    /// Whether the value is historical (sent late, not the current value).
    #[prost(bool, optional, tag = "5")]
    pub is_historical: Option<bool>,
    /// Whether a host should not store it as a tag.
    #[prost(bool, optional, tag = "6")]
    pub is_transient: Option<bool>,
    /// Whether the value is null.
    #[prost(bool, optional, tag = "7")]
    pub is_null: Option<bool>,
    /// Metadata (files, multi-part values).
    #[prost(message, optional, tag = "8")]
    pub metadata: Option<MetaData>,
    /// Properties: description, read-only, unit.
    #[prost(message, optional, tag = "9")]
    pub properties: Option<PropertySet>,
    /// The value.
    #[prost(oneof = "MetricValue", tags = "10, 11, 12, 13, 14, 15, 16")]
    pub value: Option<MetricValue>,
}

/// A metric's value, in the field its datatype says.
#[derive(Clone, PartialEq, prost::Oneof)]
pub enum MetricValue {
    /// Int8, Int16, Int32, UInt8, UInt16, UInt32.
    #[prost(uint32, tag = "10")]
    IntValue(u32),
    /// Int64, UInt64, DateTime.
    #[prost(uint64, tag = "11")]
    LongValue(u64),
    /// Float.
    #[prost(float, tag = "12")]
    FloatValue(f32),
    /// Double.
    #[prost(double, tag = "13")]
    DoubleValue(f64),
    /// Boolean.
    #[prost(bool, tag = "14")]
    BooleanValue(bool),
    /// String, Text, UUID.
    #[prost(string, tag = "15")]
    StringValue(String),
    /// Bytes, File, arrays.
    #[prost(bytes = "vec", tag = "16")]
    BytesValue(Vec<u8>),
}

/// A metric's metadata.
#[derive(Clone, PartialEq, prost::Message)]
pub struct MetaData {
    /// Part of a multi-part value.
    #[prost(bool, optional, tag = "1")]
    pub is_multi_part: Option<bool>,
    /// Content type.
    #[prost(string, optional, tag = "2")]
    pub content_type: Option<String>,
    /// Size in bytes.
    #[prost(uint64, optional, tag = "3")]
    pub size: Option<u64>,
    /// Sequence number of a part.
    #[prost(uint64, optional, tag = "4")]
    pub seq: Option<u64>,
    /// File name.
    #[prost(string, optional, tag = "5")]
    pub file_name: Option<String>,
    /// File type.
    #[prost(string, optional, tag = "6")]
    pub file_type: Option<String>,
    /// MD5 sum.
    #[prost(string, optional, tag = "7")]
    pub md5: Option<String>,
    /// Description.
    #[prost(string, optional, tag = "8")]
    pub description: Option<String>,
}

/// Properties: keys and values side by side.
#[derive(Clone, PartialEq, prost::Message)]
pub struct PropertySet {
    /// The keys.
    #[prost(string, repeated, tag = "1")]
    pub keys: Vec<String>,
    /// The values, one per key.
    #[prost(message, repeated, tag = "2")]
    pub values: Vec<PropertyValue>,
}

/// One property's value.
#[derive(Clone, PartialEq, prost::Message)]
pub struct PropertyValue {
    /// The datatype ([`DataType`](crate::metric::DataType) as a number).
    #[prost(uint32, optional, tag = "1")]
    pub r#type: Option<u32>,
    /// Whether the value is null.
    #[prost(bool, optional, tag = "2")]
    pub is_null: Option<bool>,
    /// The value.
    #[prost(oneof = "PropertyValueKind", tags = "3, 4, 5, 6, 7, 8, 9, 10")]
    pub value: Option<PropertyValueKind>,
}

/// A property's value, in the field its type says.
#[derive(Clone, PartialEq, prost::Oneof)]
pub enum PropertyValueKind {
    /// Small integers.
    #[prost(uint32, tag = "3")]
    IntValue(u32),
    /// 64-bit integers.
    #[prost(uint64, tag = "4")]
    LongValue(u64),
    /// Float.
    #[prost(float, tag = "5")]
    FloatValue(f32),
    /// Double.
    #[prost(double, tag = "6")]
    DoubleValue(f64),
    /// Boolean.
    #[prost(bool, tag = "7")]
    BooleanValue(bool),
    /// String.
    #[prost(string, tag = "8")]
    StringValue(String),
    /// A nested property set.
    #[prost(message, tag = "9")]
    PropertysetValue(PropertySet),
    /// A list of property sets.
    #[prost(message, tag = "10")]
    PropertysetsValue(PropertySetList),
}

/// A list of property sets.
#[derive(Clone, PartialEq, prost::Message)]
pub struct PropertySetList {
    /// The sets.
    #[prost(message, repeated, tag = "1")]
    pub propertyset: Vec<PropertySet>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use prost::Message;

    /// Commands are network input: any bytes decode to a payload or an error, never a panic,
    /// and whatever decodes goes through the value conversion without one either.
    #[test]
    fn arbitrary_bytes_never_panic_the_decoder_or_the_conversion() {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let valid = Payload {
            timestamp: Some(1),
            metrics: vec![Metric {
                name: Some("speed".into()),
                alias: Some(3),
                datatype: Some(6),
                value: Some(MetricValue::IntValue(7)),
                ..Metric::default()
            }],
            seq: Some(2),
            ..Payload::default()
        }
        .encode_to_vec();
        for round in 0..20_000 {
            let len = (next() % 64) as usize;
            let mut bytes: Vec<u8> = if round % 2 == 0 {
                (0..len).map(|_| next() as u8).collect()
            } else {
                // A valid payload with a few bytes changed: deeper into the decoder.
                let mut b = valid.clone();
                for _ in 0..1 + next() % 3 {
                    let i = (next() as usize) % b.len();
                    b[i] = next() as u8;
                }
                b
            };
            bytes.truncate(len.max(1) * 2);
            if let Ok(p) = Payload::decode(bytes.as_slice()) {
                for m in &p.metrics {
                    for ty in [
                        plc_core::IecType::Sint,
                        plc_core::IecType::Ltime,
                        plc_core::IecType::String,
                    ] {
                        let _ = crate::metric::from_payload(ty, m.value.as_ref());
                    }
                }
            }
        }
        assert!(Payload::decode(valid.as_slice()).is_ok());
    }
}
