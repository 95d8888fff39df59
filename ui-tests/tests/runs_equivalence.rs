//! The derive's loops over runs of fields and of bit-mapped bools give the images and values
//! that field-by-field code gives, for random declarations (every kind of type, aliases,
//! structures, bools mapped in order and out of order): `runs/generated.rs`, written by
//! `tests/generated.rs`.
#![allow(clippy::all)]

include!("runs/generated.rs");
