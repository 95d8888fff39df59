//! The columns of a CSV variable list, read by the importer and written by the export.

/// The CSV columns: first those of the seed 000 framework's tooling (`name` .. `initial`), then
/// the rest of a variable's fields, so that nothing of a declaration is lost.
pub const COLUMNS: [&str; 13] = [
    "name",
    "type",
    "direction",
    "link",
    "description",
    "initial",
    "source",
    "bit",
    "max_length",
    "nonvolatile",
    "read_only",
    "at",
    "dims",
];
