//! Limits on strings, arrays, structures and images (the JSON variable-list format, the variable-editor rules).

/// Largest string capacity in bytes (at most 255 in both the JSON variable-list format and the variable-editor rules).
pub const MAX_STRING_CAPACITY: usize = 255;
/// String capacity when a declaration gives none (the JSON variable-list format: `max_length` default 64).
pub const DEFAULT_STRING_CAPACITY: usize = 64;
/// Most dimensions an array variable may have (the variable-editor rules).
pub const MAX_ARRAY_DIMS: usize = 3;
/// Most items an array may hold, all dimensions multiplied (the variable-editor rules).
pub const MAX_ARRAY_ITEMS: usize = 65_535;
/// Most levels of structures in one another: a structure's members may be structures, to this
/// depth (a `GlobalMemory` field of a structure type is level 1).
pub const MAX_STRUCT_DEPTH: usize = 8;
/// A program's whole image must stay below this many bytes (offsets are 32-bit in the layout
/// hash and in the tools' formats).
pub const MAX_IMAGE_BYTES: u64 = 1 << 32;

/// Whether `n` is a valid string capacity (1..=255).
///
/// ```
/// assert!(plc_rules::capacity::is_valid_string_capacity(255));
/// assert!(!plc_rules::capacity::is_valid_string_capacity(0));
/// ```
pub const fn is_valid_string_capacity(n: usize) -> bool {
    n >= 1 && n <= MAX_STRING_CAPACITY
}
