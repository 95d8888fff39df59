//! `plc export <segment>`: the running program's declaration as a JSON variable list in seed
//! 000's format (plus direction, read_only, at and dims, which plc-vars adds).

use super::Error;
use plc_io::shm::{DynSegment, LayoutDescriptor};
use serde_json::{Map, Value, json};

/// The JSON variable list of a descriptor.
pub fn to_json(desc: &LayoutDescriptor) -> Value {
    let mut vars = Map::new();
    for v in &desc.variables {
        let mut o = Map::new();
        let ty = match v.rust_type.as_str() {
            t if v.iec_type == plc_core::IecType::String => {
                let _ = t;
                "string".to_string()
            }
            _ if matches!(v.iec_type.family(), plc_core::TypeFamily::BitString) => {
                v.iec_type.name().to_string()
            }
            _ => v.iec_type.rust_name().to_string(),
        };
        o.insert("type".into(), json!(ty));
        if let Some(l) = &v.link {
            o.insert("link".into(), json!(l));
        }
        if !v.description.is_empty() {
            o.insert("description".into(), json!(v.description));
        }
        if let Some(i) = &v.initial
            && let Ok(j) = serde_json::from_str::<Value>(i)
        {
            o.insert("initial".into(), j);
        }
        if v.nonvolatile {
            o.insert("nonvolatile".into(), json!(true));
        }
        if v.iec_type == plc_core::IecType::String {
            o.insert("max_length".into(), json!(v.string_capacity()));
        }
        if let Some(b) = v.bit {
            o.insert("source".into(), json!(desc.variables[b.source].name));
            o.insert("bit".into(), json!(b.bit));
        }
        if v.direction != plc_core::Direction::Internal && v.bit.is_none() && v.address.is_none() {
            o.insert("direction".into(), json!(v.direction.name()));
        }
        if v.access == plc_core::Access::ReadOnly {
            o.insert("read_only".into(), json!(true));
        }
        if let Some(a) = &v.address {
            o.insert("at".into(), json!(a));
        }
        if !v.dims.is_empty() {
            o.insert("dims".into(), json!(v.dims));
        }
        vars.insert(v.name.clone(), Value::Object(o));
    }
    json!({ "variables": vars })
}

pub fn run(segment: &str) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    println!(
        "{}",
        serde_json::to_string_pretty(&to_json(seg.descriptor()))?
    );
    Ok(())
}
