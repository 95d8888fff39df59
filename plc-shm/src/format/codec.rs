//! Values in image bytes, by descriptor: little endian numbers, a bool is any non-zero byte,
//! strings are zero padded UTF-8 (bytes from outside that are not UTF-8 give the valid prefix).

use super::descriptor::VarDescriptor;
use plc_core::{FixedString, IecType, TypeFamily, Value};

impl VarDescriptor {
    /// Element `element` of this variable or member in `image`, a whole image (from
    /// [`DynSegment::snapshot_bytes`](crate::DynSegment::snapshot_bytes)): the one way a tool
    /// without the program's types reads a value. A top-level variable is
    /// `seg.descriptor().variables[index]`; a member or element found by its path is
    /// [`PathLocation::var`](crate::PathLocation::var) (element 0); a member a tool walks to
    /// holds its absolute offset. `None` if the element or its bytes are not there.
    ///
    /// ```no_run
    /// let seg = plc_shm::DynSegment::attach("tensile_tester")?;
    /// let image = seg.snapshot_bytes()?;
    /// let force = seg.locate("force_kn")?;
    /// println!("{:?}", force.var.value_in(&image, 0));
    /// # Ok::<(), plc_shm::ShmError>(())
    /// ```
    pub fn value_in(&self, image: &[u8], element: usize) -> Option<Value> {
        let var = self;
        if element >= var.elements() {
            return None;
        }
        let size = var.element_size();
        let start = var.offset + element * size;
        let bytes = image.get(start..start + size)?;
        Some(decode(var.iec_type, bytes))
    }
}

/// The value of type `ty` that an element's `bytes` hold (all of its bytes: a STRING's
/// capacity, a number's width).
pub fn decode(ty: IecType, bytes: &[u8]) -> Value {
    let size = bytes.len();
    let mut w = [0u8; 8];
    if ty != IecType::String {
        w[..size.min(8)].copy_from_slice(&bytes[..size.min(8)]);
    }
    match ty.family() {
        TypeFamily::Bool => Value::Bool(bytes.iter().any(|&b| b != 0)),
        TypeFamily::String => {
            let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
            let text = match std::str::from_utf8(&bytes[..end]) {
                Ok(s) => s,
                Err(e) => std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default(),
            };
            Value::Text(FixedString::from_str_truncate(text))
        }
        _ => Value::from_raw_bits(u64::from_le_bytes(w), ty, ty.bits()),
    }
}

/// Writes `value`, already fitted to type `ty` (see [`Value::fit`]), as an element's `bytes`:
/// the inverse of [`decode`]. A STRING is its text zero padded; `false` if the text does not
/// fit the bytes, and then nothing is written.
pub fn encode(ty: IecType, value: &Value, bytes: &mut [u8]) -> bool {
    match (ty.family(), value) {
        (TypeFamily::String, Value::Text(t)) => {
            let text = t.as_str().as_bytes();
            if text.len() > bytes.len() {
                return false;
            }
            bytes.fill(0);
            bytes[..text.len()].copy_from_slice(text);
        }
        _ => {
            let raw = value.to_raw_bits(ty).to_le_bytes();
            let n = bytes.len().min(8);
            bytes[..n].copy_from_slice(&raw[..n]);
        }
    }
    true
}
