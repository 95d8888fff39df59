//! Values in image bytes, by descriptor: little endian numbers, a bool is any non-zero byte,
//! strings are zero padded UTF-8 (bytes from outside that are not UTF-8 give the valid prefix).

use crate::descriptor::VarDescriptor;
use plc_core::{FixedString, IecType, TypeFamily, Value};

/// Decodes element `element` of `var` from a whole image.
pub fn decode(image: &[u8], var: &VarDescriptor, element: usize) -> Option<Value> {
    if element >= var.elements() {
        return None;
    }
    let size = var.element_size();
    let start = var.offset + element * size;
    let bytes = image.get(start..start + size)?;
    let mut w = [0u8; 8];
    if var.iec_type != IecType::String {
        w[..size.min(8)].copy_from_slice(&bytes[..size.min(8)]);
    }
    Some(match var.iec_type.family() {
        TypeFamily::Bool => Value::Bool(bytes.iter().any(|&b| b != 0)),
        TypeFamily::String => {
            let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
            let text = match std::str::from_utf8(&bytes[..end]) {
                Ok(s) => s,
                Err(e) => std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default(),
            };
            Value::Text(FixedString::from_str_truncate(text))
        }
        _ => Value::from_raw_bits(u64::from_le_bytes(w), var.iec_type, var.iec_type.bits()),
    })
}
