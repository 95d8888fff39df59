//! The way back: a declaration (a compiled type's `VARIABLES`, or a running program's
//! descriptor) as a JSON variable list in the JSON variable-list format, plus the keys plc-vars
//! adds; and the same as CSV. Structured variables export their types into the list's `types`
//! section, so that importing the list again gives the same structs (a type's description is
//! not in the descriptor, so it does not come back).

use plc_core::{Access, Direction, GlobalMemory, IecType, TypeFamily};
use plc_rules::capacity::MAX_STRUCT_DEPTH;
use plc_shm::{LayoutDescriptor, VarDescriptor};
use serde_json::{Map, Value, json};

/// The JSON variable list of a descriptor: a `types` section with each structure type once
/// (by its type name, members before the types that use them), then the variables, each with
/// its `"alarm"` if it declares one.
///
/// Fails if two structured variables give one type name different members (two structure
/// types declared with the same `name`), naming both, or on a descriptor that nests
/// structures deeper than a declaration can.
pub fn descriptor_to_json(desc: &LayoutDescriptor) -> Result<Value, String> {
    let mut types = Types::default();
    let mut vars = Map::new();
    for v in &desc.variables {
        vars.insert(v.name.clone(), var_json(v, &desc.variables, &mut types, 0)?);
    }
    let mut list = Map::new();
    if !types.json.is_empty() {
        list.insert("types".into(), Value::Object(types.json));
    }
    list.insert("variables".into(), Value::Object(vars));
    let mut list = Value::Object(list);
    super::export_alarms::add(&mut list, &desc.variables, &desc.alarms);
    Ok(list)
}

/// The structure types met so far: their JSON, and the variable each was first seen in (for
/// the error naming both declarations).
#[derive(Default)]
struct Types {
    json: Map<String, Value>,
    first_seen: Map<String, Value>,
}

/// One variable (or member), its type recorded in `types` if it is a structure. `siblings`
/// are the variables a bit-mapped bool's source index refers to.
fn var_json(
    v: &VarDescriptor,
    siblings: &[VarDescriptor],
    types: &mut Types,
    depth: usize,
) -> Result<Value, String> {
    let mut o = Map::new();
    let structure = match (&v.type_name, v.members.is_empty()) {
        (Some(name), false) => Some(name),
        _ => None,
    };
    // A standard function block is named, not declared: the importer knows it.
    let standard = structure.is_some_and(|name| {
        super::standard::standard_with_members(name, v.members.iter().map(|m| m.name.as_str()))
            .is_some()
    });
    let ty = match (structure, v.iec_type.family()) {
        (Some(name), _) => name.clone(),
        (None, TypeFamily::String) => "string".to_string(),
        // No Rust primitive names these: the IEC name (`"WORD"`, `"LTIME"`).
        (None, TypeFamily::BitString | TypeFamily::Time) => v.iec_type.name().to_string(),
        (None, _) => v.iec_type.rust_name().to_string(),
    };
    o.insert("type".into(), json!(ty));
    if let Some(name) = structure
        && !standard
    {
        type_json(name, v, types, depth)?;
    }
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
    if v.iec_type == IecType::String && structure.is_none() {
        o.insert("max_length".into(), json!(v.string_capacity()));
    }
    if let Some(b) = v.bit
        && let Some(source) = siblings.get(b.source)
    {
        o.insert("source".into(), json!(source.name));
        o.insert("bit".into(), json!(b.bit));
    }
    // Implied directions (internal, from `at`, from a source word) are not written.
    if v.direction != Direction::Internal && v.bit.is_none() && v.address.is_none() {
        o.insert("direction".into(), json!(v.direction.name()));
    }
    if v.access == Access::ReadOnly && structure.is_none() {
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
    if let Some(u) = &v.unit {
        o.insert("unit".into(), json!(u));
    }
    if let Some(d) = v.deadband {
        o.insert("deadband".into(), json!(d));
    }
    Ok(Value::Object(o))
}

/// Records the type of the structured variable `v`: its members' types first, then its own
/// entry; the same name with other members is an error naming both variables.
fn type_json(name: &str, v: &VarDescriptor, types: &mut Types, depth: usize) -> Result<(), String> {
    if depth >= MAX_STRUCT_DEPTH {
        return Err(format!(
            "{:?} nests structures more than {MAX_STRUCT_DEPTH} levels deep: the descriptor is \
             damaged",
            v.name
        ));
    }
    let mut members = Map::new();
    for m in &v.members {
        members.insert(m.name.clone(), var_json(m, &v.members, types, depth + 1)?);
    }
    let def = json!({ "variables": members });
    match types.json.get(name) {
        // By text: the members' order is part of the type (its layout).
        Some(known) if serde_json::to_string(known).ok() == serde_json::to_string(&def).ok() => {
            Ok(())
        }
        Some(_) => Err(format!(
            "two structure types are named {name:?} with different members (one in {}, one \
             in {:?}): give one another name (`#[plc(name = \"...\")]`), as a list names each \
             type once",
            types.first_seen[name], v.name
        )),
        None => {
            types.json.insert(name.to_string(), def);
            types.first_seen.insert(name.to_string(), json!(v.name));
            Ok(())
        }
    }
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
/// let json = plc_import::export_json::<Gm>().unwrap();
/// assert!(json.contains("\"press_home_offset_mm\""));
/// assert!(json.contains("\"nonvolatile\": true"));
/// ```
pub fn export_json<T: GlobalMemory>() -> Result<String, String> {
    serde_json::to_string_pretty(&type_to_json::<T>()?).map_err(|e| e.to_string())
}

/// The list of a compiled type: its descriptor's, alarms included.
fn type_to_json<T: GlobalMemory>() -> Result<Value, String> {
    descriptor_to_json(&LayoutDescriptor::of::<T>())
}

/// The CSV variable list of a descriptor: the columns of [`COLUMNS`](super::COLUMNS) (and
/// [`ALARM_COLUMNS`](super::ALARM_COLUMNS) if a variable has an alarm), the
/// same content as [`descriptor_to_json`] (each type as a `STRUCT` row and its members' rows,
/// before the variables), with its errors.
pub fn descriptor_to_csv(desc: &LayoutDescriptor) -> Result<String, String> {
    Ok(super::csv_write::to_csv(&descriptor_to_json(desc)?))
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
/// let csv = plc_import::export_csv::<Gm>().unwrap();
/// assert_eq!(
///     csv,
///     "name,type,direction,link,description,initial,source,bit,max_length,nonvolatile,read_only,at,dims,ux,quantity,unit,deadband\r\n\
///      press_home_offset_mm,f64,,,\"Offset, in mm\",12.5,,,,true,,,,,,,\r\n"
/// );
/// ```
pub fn export_csv<T: GlobalMemory>() -> Result<String, String> {
    Ok(super::csv_write::to_csv(&type_to_json::<T>()?))
}
