//! Limits on strings and arrays (the JSON variable-list format, the variable-editor rules).

/// Largest string capacity in bytes (at most 255 in both the JSON variable-list format and the variable-editor rules).
pub const MAX_STRING_CAPACITY: usize = 255;
/// String capacity when a declaration gives none (the JSON variable-list format: `max_length` default 64).
pub const DEFAULT_STRING_CAPACITY: usize = 64;
/// Most dimensions an array variable may have (the variable-editor rules).
pub const MAX_ARRAY_DIMS: usize = 3;
/// Most items an array may hold, all dimensions multiplied (the variable-editor rules).
pub const MAX_ARRAY_ITEMS: usize = 65_535;

/// Whether `n` is a valid string capacity (1..=255).
///
/// ```
/// assert!(plc_rules::capacity::is_valid_string_capacity(255));
/// assert!(!plc_rules::capacity::is_valid_string_capacity(0));
/// ```
pub const fn is_valid_string_capacity(n: usize) -> bool {
    n >= 1 && n <= MAX_STRING_CAPACITY
}
