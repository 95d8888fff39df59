//! Which derive a struct is under: the program's variables or a structure type.

/// Which derive: a program's variables, or a structure type for their fields.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    GlobalMemory,
    PlcStruct,
}

impl Kind {
    /// The derive's name, as messages give it.
    pub fn name(self) -> &'static str {
        match self {
            Kind::GlobalMemory => "GlobalMemory",
            Kind::PlcStruct => "PlcStruct",
        }
    }

    /// A struct with named fields of this kind, for messages.
    pub fn example(self) -> &'static str {
        match self {
            Kind::GlobalMemory => "struct Gm { speed: i32 }",
            Kind::PlcStruct => "struct Axis { pos: f64 }",
        }
    }

    /// What one field is, as messages call it.
    pub fn field(self) -> &'static str {
        match self {
            Kind::GlobalMemory => "variable",
            Kind::PlcStruct => "member",
        }
    }
}
