//! Limits on strings and arrays (seeds 000 and 003).

/// Largest string capacity in bytes (seed 000: `max_length` at most 255; seed 003: 255).
pub const MAX_STRING_CAPACITY: usize = 255;
/// String capacity when a declaration gives none (seed 000: `max_length` default 64).
pub const DEFAULT_STRING_CAPACITY: usize = 64;
/// Most dimensions an array variable may have (seed 003).
pub const MAX_ARRAY_DIMS: usize = 3;
/// Most items an array may hold, all dimensions multiplied (seed 003).
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
