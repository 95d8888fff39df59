//! The way back: a declaration (a compiled type's `VARIABLES`, or a running program's
//! descriptor) as a JSON variable list in the JSON variable-list format, plus the keys plc-vars adds; and
//! the same as CSV.

use crate::shm::LayoutDescriptor;
use plc_core::{Access, Direction, GlobalMemory, IecType, TypeFamily};
use serde_json::{Map, Value, json};

/// The JSON variable list of a descriptor.
pub fn descriptor_to_json(desc: &LayoutDescriptor) -> Value {
    let mut vars = Map::new();
    for v in &desc.variables {
        let mut o = Map::new();
        let ty = match v.iec_type.family() {
            TypeFamily::String => "string".to_string(),
            // No Rust primitive names these: the IEC name (`"WORD"`, `"LTIME"`).
            TypeFamily::BitString | TypeFamily::Time => v.iec_type.name().to_string(),
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
        if v.iec_type == IecType::String {
            o.insert("max_length".into(), json!(v.string_capacity()));
        }
        if let Some(b) = v.bit {
            o.insert("source".into(), json!(desc.variables[b.source].name));
            o.insert("bit".into(), json!(b.bit));
        }
        // Implied directions (internal, from `at`, from a source word) are not written.
        if v.direction != Direction::Internal && v.bit.is_none() && v.address.is_none() {
            o.insert("direction".into(), json!(v.direction.name()));
        }
        if v.access == Access::ReadOnly {
            o.insert("read_only".into(), json!(true));
        }
        if let Some(a) = &v.address {
            o.insert("at".into(), json!(a));
        }
        if !v.dims.is_empty() {
            o.insert("dims".into(), json!(v.dims));
        }
        if v.ux {
            o.insert("ux".into(), json!(true));
        }
        if let Some(q) = &v.quantity {
            o.insert("quantity".into(), json!(q));
        }
        vars.insert(v.name.clone(), Value::Object(o));
    }
    json!({ "variables": vars })
}

/// The JSON variable list of a compiled `GlobalMemory` type.
///
/// ```
/// use plc_core::GlobalMemory;
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     #[plc(nonvolatile, initial = 12.5)]
///     press_home_offset_mm: f64,
/// }
/// let json = plc_io::import::export_json::<Gm>();
/// assert!(json.contains("\"press_home_offset_mm\""));
/// assert!(json.contains("\"nonvolatile\": true"));
/// ```
pub fn export_json<T: GlobalMemory>() -> String {
    let value = descriptor_to_json(&LayoutDescriptor::of::<T>());
    serde_json::to_string_pretty(&value).unwrap_or_default()
}

/// The CSV variable list of a descriptor: the columns of [`COLUMNS`](super::COLUMNS), the
/// same content as [`descriptor_to_json`].
pub fn descriptor_to_csv(desc: &LayoutDescriptor) -> String {
    super::csv_write::to_csv(&descriptor_to_json(desc))
}

/// The CSV variable list of a compiled `GlobalMemory` type (as [`export_json`], as CSV).
///
/// ```
/// use plc_core::GlobalMemory;
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     /// Offset, in mm
///     #[plc(nonvolatile, initial = 12.5)]
///     press_home_offset_mm: f64,
/// }
/// let csv = plc_io::import::export_csv::<Gm>();
/// assert_eq!(
///     csv,
///     "name,type,direction,link,description,initial,source,bit,max_length,nonvolatile,read_only,at,dims,ux,quantity\r\n\
///      press_home_offset_mm,f64,,,\"Offset, in mm\",12.5,,,,true,,,,,\r\n"
/// );
/// ```
pub fn export_csv<T: GlobalMemory>() -> String {
    descriptor_to_csv(&LayoutDescriptor::of::<T>())
}
