//! How plc-vars variables appear in OPC UA (IEC 61131-3 types to OPC UA Part 3/6 built-in
//! types, access and direction to AccessLevel, paths to NodeIds, refusals and owner states to
//! status codes), and back for writes. Pure functions: the server and its tests share them.

use opcua::nodes::AccessLevel;
use opcua::types::{
    Array, DataTypeId, DataValue, DateTime, NodeId, NumericRange, StatusCode, TimestampsToReturn,
    Variant, VariantScalarTypeId,
};
use plc_core::{FixedString, IecType, Value, ValueError};
use plc_shm::{OwnerState, ShmError, VarDescriptor};

/// The NodeId of the object that stands for a program (its segment) in its namespace: numeric,
/// so it never collides with a variable's string NodeId.
pub const PROGRAM_OBJECT_ID: u32 = 1;

/// The namespace URI of a segment's variables.
pub fn namespace_uri(segment: &str) -> String {
    format!("urn:plc-vars:{segment}")
}

/// The NodeId of the variable at `path` (the path `plc get` takes, as declared).
pub fn variable_node_id(ns: u16, path: &str) -> NodeId {
    NodeId::new(ns, path)
}

/// The OPC UA built-in type of one element of an IEC type.
pub fn scalar_type(ty: IecType) -> VariantScalarTypeId {
    use VariantScalarTypeId as S;
    match ty {
        IecType::Bool => S::Boolean,
        IecType::Sint => S::SByte,
        IecType::Int => S::Int16,
        IecType::Dint => S::Int32,
        IecType::Lint => S::Int64,
        IecType::Usint | IecType::Byte => S::Byte,
        IecType::Uint | IecType::Word => S::UInt16,
        IecType::Udint | IecType::Dword => S::UInt32,
        IecType::Ulint | IecType::Lword => S::UInt64,
        IecType::Real => S::Float,
        // OPC UA's Duration: a Double of milliseconds.
        IecType::Lreal | IecType::Ltime => S::Double,
        IecType::String => S::String,
    }
}

/// The DataType attribute of a variable of IEC type `ty`.
pub fn data_type(ty: IecType) -> DataTypeId {
    use VariantScalarTypeId as S;
    if ty == IecType::Ltime {
        return DataTypeId::Duration;
    }
    match scalar_type(ty) {
        S::Boolean => DataTypeId::Boolean,
        S::SByte => DataTypeId::SByte,
        S::Byte => DataTypeId::Byte,
        S::Int16 => DataTypeId::Int16,
        S::UInt16 => DataTypeId::UInt16,
        S::Int32 => DataTypeId::Int32,
        S::UInt32 => DataTypeId::UInt32,
        S::Int64 => DataTypeId::Int64,
        S::UInt64 => DataTypeId::UInt64,
        S::Float => DataTypeId::Float,
        S::Double => DataTypeId::Double,
        _ => DataTypeId::String,
    }
}

/// ValueRank and ArrayDimensions: -1 (scalar) and none, or the number of dimensions and their
/// lengths.
pub fn value_rank(var: &VarDescriptor) -> (i32, Option<Vec<u32>>) {
    if var.dims.is_empty() {
        (-1, None)
    } else {
        let dims = var
            .dims
            .iter()
            .map(|&d| u32::try_from(d).unwrap_or(u32::MAX));
        (var.dims.len() as i32, Some(dims.collect()))
    }
}

/// AccessLevel: CurrentRead, plus CurrentWrite where a tool may write the variable (read-write,
/// neither input nor status). Which session may write is the UserAccessLevel's business.
pub fn access_level(var: &VarDescriptor) -> AccessLevel {
    access_level_for(var.writable_from_outside())
}

/// AccessLevel of a node tools may write or not (inside a structure, IN parameters may be
/// written, read-only members not).
pub fn access_level_for(writable: bool) -> AccessLevel {
    if writable {
        AccessLevel::CURRENT_READ | AccessLevel::CURRENT_WRITE
    } else {
        AccessLevel::CURRENT_READ
    }
}

/// The UserAccessLevel of a session: an anonymous one browses and reads only.
pub fn user_access_level(level: AccessLevel, anonymous: bool) -> AccessLevel {
    if anonymous {
        level - AccessLevel::CURRENT_WRITE
    } else {
        level
    }
}

/// One element as a Variant of the variable's own built-in type.
pub fn to_variant(ty: IecType, value: Value) -> Variant {
    use VariantScalarTypeId as S;
    match (scalar_type(ty), value) {
        (S::Boolean, Value::Bool(b)) => Variant::Boolean(b),
        (S::SByte, Value::Int(i)) => Variant::SByte(i as i8),
        (S::Int16, Value::Int(i)) => Variant::Int16(i as i16),
        (S::Int32, Value::Int(i)) => Variant::Int32(i as i32),
        (S::Int64, Value::Int(i)) => Variant::Int64(i),
        (S::Byte, Value::UInt(u)) => Variant::Byte(u as u8),
        (S::UInt16, Value::UInt(u)) => Variant::UInt16(u as u16),
        (S::UInt32, Value::UInt(u)) => Variant::UInt32(u as u32),
        (S::UInt64, Value::UInt(u)) => Variant::UInt64(u),
        (S::Float, Value::Real(r)) => Variant::Float(r as f32),
        (S::Double, Value::Real(r)) => Variant::Double(r),
        (S::Double, Value::Time(t)) => Variant::Double(t.as_nanos() as f64 / 1e6),
        (S::String, Value::Text(t)) => Variant::from(t.as_str()),
        // A decoder gives each type its own kind; anything else is a damaged descriptor.
        _ => Variant::Empty,
    }
}

/// A whole variable as a Variant: a scalar, or an array with its dimensions (row-major, as the
/// image stores it).
pub fn to_value_variant(var: &VarDescriptor, elements: Vec<Value>) -> Variant {
    let items: Vec<Variant> = elements
        .into_iter()
        .map(|v| to_variant(var.iec_type, v))
        .collect();
    if var.dims.is_empty() {
        return items.into_iter().next().unwrap_or(Variant::Empty);
    }
    let ty = scalar_type(var.iec_type);
    let array = match value_rank(var).1 {
        Some(dims) if dims.len() > 1 => Array::new_multi(ty, items, dims),
        _ => Array::new(ty, items),
    };
    array.map(Variant::from).unwrap_or(Variant::Empty)
}

/// A written Variant element as a plc-vars value, before the variable's own checks (`fit`):
/// any number kind is accepted for any number type; the range, and NaN or an infinity for a
/// REAL, are the one write check's (`plc_core::write::check`), as for every tool.
pub fn from_variant(v: &Variant) -> Result<Value, StatusCode> {
    let value = match *v {
        Variant::Boolean(b) => Value::Bool(b),
        Variant::SByte(i) => Value::Int(i.into()),
        Variant::Int16(i) => Value::Int(i.into()),
        Variant::Int32(i) => Value::Int(i.into()),
        Variant::Int64(i) => Value::Int(i),
        Variant::Byte(u) => Value::UInt(u.into()),
        Variant::UInt16(u) => Value::UInt(u.into()),
        Variant::UInt32(u) => Value::UInt(u.into()),
        Variant::UInt64(u) => Value::UInt(u),
        Variant::Float(r) => Value::Real(r.into()),
        Variant::Double(r) => Value::Real(r),
        Variant::String(ref s) => {
            let text = s.as_ref();
            let mut fixed = FixedString::<255>::new();
            fixed.try_set(text).map_err(|_| StatusCode::BadOutOfRange)?;
            Value::Text(fixed)
        }
        _ => return Err(StatusCode::BadTypeMismatch),
    };
    Ok(value)
}

/// A written Duration (milliseconds) as an LTIME: negative, NaN or beyond LTIME's range is out
/// of range, a number of another kind a type mismatch.
pub fn duration_from(value: Value) -> Result<Value, StatusCode> {
    let ms = match value {
        Value::Real(ms) => ms,
        Value::Int(ms) => ms as f64,
        Value::UInt(ms) => ms as f64,
        _ => return Err(StatusCode::BadTypeMismatch),
    };
    let ns = (ms * 1e6).round();
    if !(0.0..=i64::MAX as f64).contains(&ns) {
        return Err(StatusCode::BadOutOfRange);
    }
    Ok(Value::Time(plc_core::Time::from_nanos(ns as i64)))
}

/// The elements of a written Value attribute: one for a scalar; for an array, every element
/// (the dimensions must match the variable's). Durations arrive as milliseconds.
pub fn written_elements(var: &VarDescriptor, v: &Variant) -> Result<Vec<Value>, StatusCode> {
    let elements = written_values(var, v)?;
    if var.iec_type == IecType::Ltime {
        return elements.into_iter().map(duration_from).collect();
    }
    Ok(elements)
}

/// The elements a write with an index range sets, as (row-major element, value): all of them
/// without a range; for a one-dimensional array an index (`3`) or a range (`2:5`); for an
/// array of more dimensions one index or range per dimension (`0:1,2`), as OPC UA Part 4
/// (NumericRange) writes them. The value holds exactly the selected elements, as an array (one
/// element may also come as a scalar). A range past the array's end is `BadIndexRangeNoData`,
/// one that does not fit its dimensions `BadIndexRangeInvalid`.
pub fn written_range(
    var: &VarDescriptor,
    v: &Variant,
    range: &NumericRange,
) -> Result<Vec<(usize, Value)>, StatusCode> {
    if range.is_none() {
        return Ok(written_elements(var, v)?.into_iter().enumerate().collect());
    }
    if var.dims.is_empty() {
        return Err(StatusCode::BadIndexRangeInvalid);
    }
    let selected = selected_elements(&var.dims, range)?;
    let values: Vec<&Variant> = match v {
        Variant::Array(a) => a.values.iter().collect(),
        Variant::Empty => return Err(StatusCode::BadTypeMismatch),
        scalar => vec![scalar],
    };
    if values.len() != selected.len() {
        return Err(StatusCode::BadTypeMismatch);
    }
    selected
        .into_iter()
        .zip(values)
        .map(|(e, v)| Ok((e, written_element(var, v)?)))
        .collect()
}

/// The row-major elements an index range selects in an array of `dims`, in row-major order;
/// checked against the dimensions before any is listed, so at most the array's elements.
fn selected_elements(dims: &[usize], range: &NumericRange) -> Result<Vec<usize>, StatusCode> {
    let parts: Vec<&NumericRange> = match range {
        NumericRange::MultipleRanges(parts) => parts.iter().collect(),
        one => vec![one],
    };
    if parts.len() != dims.len() {
        return Err(StatusCode::BadIndexRangeInvalid);
    }
    let mut spans = Vec::with_capacity(dims.len());
    for (part, &dim) in parts.into_iter().zip(dims) {
        let (lo, hi) = match *part {
            NumericRange::Index(i) => (i as usize, i as usize),
            // Part 4: the first index of a range is below the second.
            NumericRange::Range(lo, hi) if lo < hi => (lo as usize, hi as usize),
            _ => return Err(StatusCode::BadIndexRangeInvalid),
        };
        if hi >= dim {
            return Err(StatusCode::BadIndexRangeNoData);
        }
        spans.push((lo, hi));
    }
    // Row-major: the last dimension varies fastest.
    let mut selected = vec![0usize];
    for (&(lo, hi), &dim) in spans.iter().zip(dims) {
        selected = selected
            .into_iter()
            .flat_map(|base| (lo..=hi).map(move |i| base * dim + i))
            .collect();
    }
    Ok(selected)
}

/// One written element of an array variable (a write with an index range).
pub fn written_element(var: &VarDescriptor, v: &Variant) -> Result<Value, StatusCode> {
    let value = from_variant(v)?;
    if var.iec_type == IecType::Ltime {
        return duration_from(value);
    }
    Ok(value)
}

fn written_values(var: &VarDescriptor, v: &Variant) -> Result<Vec<Value>, StatusCode> {
    match (var.dims.is_empty(), v) {
        (true, Variant::Array(_)) | (false, Variant::Empty) => Err(StatusCode::BadTypeMismatch),
        (true, scalar) => Ok(vec![from_variant(scalar)?]),
        (false, Variant::Array(array)) => {
            let dims_match = match &array.dimensions {
                Some(d) if d.len() > 1 => value_rank(var).1.as_deref() == Some(d.as_slice()),
                _ => var.dims.len() == 1,
            };
            if !dims_match || array.values.len() != var.elements() {
                return Err(StatusCode::BadTypeMismatch);
            }
            array.values.iter().map(from_variant).collect()
        }
        (false, _) => Err(StatusCode::BadTypeMismatch),
    }
}

/// The status code of a write the library refused.
pub fn write_refusal(e: &ShmError) -> StatusCode {
    match e {
        ShmError::NotWritable { .. } => StatusCode::BadNotWritable,
        ShmError::UnknownVariable { .. } => StatusCode::BadNodeIdUnknown,
        ShmError::ElementOutOfRange { .. } => StatusCode::BadIndexRangeNoData,
        ShmError::Value { error, .. } => match error {
            ValueError::WrongKind { .. }
            | ValueError::Syntax { .. }
            | ValueError::Duration { .. } => StatusCode::BadTypeMismatch,
            ValueError::OutOfRange { .. }
            | ValueError::TooLong { .. }
            | ValueError::Nul { .. }
            | ValueError::NotFinite { .. } => StatusCode::BadOutOfRange,
        },
        // Held by an operator's force (`plc force`) until it is released: OPC UA's "the Node is
        // locked by a different application" says that, and that the fix is to release the
        // lock, not to change the value (BadOutOfRange), the user (BadUserAccessDenied) or the
        // node's access (BadNotWritable: its AccessLevel still allows writing, rightly).
        ShmError::Forced { .. } => StatusCode::BadLocked,
        ShmError::QueueFull(_)
        | ShmError::Busy { .. }
        | ShmError::RequestCount { .. }
        | ShmError::RequestTooLarge { .. } => StatusCode::BadTooManyOperations,
        ShmError::OwnerGone(_) | ShmError::Replaced(_) | ShmError::Closed { .. } => {
            StatusCode::BadNoCommunication
        }
        ShmError::Os { .. } | ShmError::Stuck(_) => StatusCode::BadTimeout,
        _ => StatusCode::BadInternalError,
    }
}

/// The status of values published by an owner in `state`: good while it runs; uncertain while
/// it is alive but its heartbeat stopped (the last values it published); bad once it is gone,
/// stopped or faulted (nothing updates them).
pub fn value_status(state: OwnerState) -> StatusCode {
    match state {
        OwnerState::Running => StatusCode::Good,
        OwnerState::Stalled => StatusCode::UncertainLastUsableValue,
        OwnerState::Faulted | OwnerState::Stopped | OwnerState::Gone => {
            StatusCode::BadNoCommunication
        }
    }
}

/// The status of a value whose owner's state gives `status`: a value held by a force (`forced`)
/// while the owner runs is GoodLocalOverride, OPC UA's "the value has been overridden" (Part 8:
/// a manually entered value has been forced), so a client sees the force without writing.
pub fn forced_status(status: StatusCode, forced: bool) -> StatusCode {
    if forced && status == StatusCode::Good {
        StatusCode::GoodLocalOverride
    } else {
        status
    }
}

/// Whether one of the basic values `first_leaf..first_leaf + elements` of variable `index` is
/// among `forced` ((variable index, leaf), sorted).
pub fn holds_force(
    forced: &[(usize, usize)],
    index: usize,
    first_leaf: usize,
    elements: usize,
) -> bool {
    let from = forced.partition_point(|&f| f < (index, first_leaf));
    forced
        .get(from)
        .is_some_and(|&(i, leaf)| i == index && leaf < first_leaf + elements)
}

/// A DataValue that is only a status (no value), stamped with the server's time.
pub fn status_only(status: StatusCode) -> DataValue {
    DataValue {
        value: None,
        status: Some(status),
        source_timestamp: None,
        source_picoseconds: None,
        server_timestamp: Some(DateTime::now()),
        server_picoseconds: None,
    }
}

/// `dv` with only the timestamps a client asked for (a Read's or a monitored item's
/// `TimestampsToReturn`).
pub fn keep_timestamps(mut dv: DataValue, timestamps: TimestampsToReturn) -> DataValue {
    if matches!(
        timestamps,
        TimestampsToReturn::Server | TimestampsToReturn::Neither
    ) {
        dv.source_timestamp = None;
    }
    if matches!(
        timestamps,
        TimestampsToReturn::Source | TimestampsToReturn::Neither
    ) {
        dv.server_timestamp = None;
    }
    dv
}

/// OPC UA's DateTime (100 ns ticks since 1601-01-01) of a cycle stamped `ns` nanoseconds after
/// the Unix epoch; `None` before the first cycle (stamp 0).
pub fn source_time(ns: u64) -> Option<DateTime> {
    /// Ticks from 1601-01-01 to 1970-01-01.
    const UNIX_EPOCH_TICKS: i64 = 116_444_736_000_000_000;
    if ns == 0 {
        return None;
    }
    let ticks = i64::try_from(ns / 100)
        .ok()?
        .checked_add(UNIX_EPOCH_TICKS)?;
    Some(DateTime::from(ticks))
}

#[cfg(test)]
mod tests;
