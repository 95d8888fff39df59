//! Compile-time facts about a field type, for the derive's spanned `const` assertions on types
//! only the compiler knows (aliases). Every assertion reaches the type through the one generic
//! `facts::<T>()`, so a type that is not `PlcType` at all gives one error (identical errors at
//! the same span are reported once), not one per assertion.

use crate::{IecType, PlcType, TypeFamily};

/// What the derive's assertions need to know about a field type.
#[derive(Clone, Copy, Debug)]
pub struct TypeFacts {
    iec_type: IecType,
    rank: usize,
    elements: usize,
    string_capacity: usize,
    repr_size: usize,
    /// A structure or an array of structures: none of the basic types' predicates hold.
    structured: bool,
    depth: usize,
    leaves: usize,
    alarms: &'static [crate::alarm::AlarmDecl],
}

/// The facts of field type `T`.
pub const fn facts<T: PlcType>() -> TypeFacts {
    TypeFacts {
        iec_type: T::IEC_TYPE,
        rank: T::RANK,
        elements: T::ELEMENTS,
        string_capacity: T::STRING_CAPACITY,
        repr_size: core::mem::size_of::<T::Repr>(),
        structured: T::TYPE_NAME.is_some(),
        depth: T::DEPTH,
        leaves: T::LEAVES,
        alarms: T::ALARMS,
    }
}

impl TypeFacts {
    /// Leaves of the type (see `PlcType::LEAVES`).
    pub const fn leaves(self) -> usize {
        self.leaves
    }

    /// Elements of the type (1 for a scalar or structure).
    pub const fn elements(self) -> usize {
        self.elements
    }

    /// The alarm table's part of a field of this type that declares no alarm itself: its
    /// structure's alarms, once per element (none for a basic type).
    pub const fn alarm_part(self, index: usize, base: usize) -> crate::alarm::table::Part {
        crate::alarm::table::nested(self.alarms, self.leaves, self.elements, index, base)
    }

    /// Bytes of the type's stored form in the image.
    pub const fn repr_size(self) -> usize {
        self.repr_size
    }

    /// Whether the type is an integer scalar (a bit source).
    pub const fn is_integer(self) -> bool {
        !self.structured && self.iec_type.is_integer() && self.rank == 0
    }

    /// Whether the type is a scalar `bool`.
    pub const fn is_bool(self) -> bool {
        !self.structured && matches!(self.iec_type, IecType::Bool) && self.rank == 0
    }

    /// Whether the type has at most 3 dimensions and 65,535 items, and a string capacity of
    /// 1..=255 (the variable-editor rules).
    pub const fn shape_fits(self) -> bool {
        let string_ok = !matches!(self.iec_type, IecType::String)
            || plc_rules::capacity::is_valid_string_capacity(self.string_capacity);
        self.rank <= plc_rules::capacity::MAX_ARRAY_DIMS
            && self.elements <= plc_rules::capacity::MAX_ARRAY_ITEMS
            && string_ok
    }

    /// Whether the elements are bools (a bool alarm's type).
    pub const fn has_bool_elements(self) -> bool {
        !self.structured && matches!(self.iec_type, IecType::Bool)
    }

    /// Whether the elements are numbers (a limit alarm's type).
    pub const fn has_number_elements(self) -> bool {
        !self.structured
            && matches!(
                self.iec_type.family(),
                TypeFamily::SignedInt
                    | TypeFamily::UnsignedInt
                    | TypeFamily::Real
                    | TypeFamily::BitString
            )
    }

    /// Whether the type is a structure or an array of structures.
    pub const fn is_structured(self) -> bool {
        self.structured
    }

    /// Whether the type nests structures at most `levels` deep.
    pub const fn depth_at_most(self, levels: usize) -> bool {
        self.depth <= levels
    }

    /// Whether an array type has at least one item (`[u8; 0]` has none, and no place in the
    /// image to give a variable); scalars always do.
    pub const fn has_items(self) -> bool {
        self.elements >= 1
    }

    /// Whether the type can be one I/O channel: a scalar, not an array or a string (the variable-editor rules).
    pub const fn is_channel(self) -> bool {
        !self.structured && self.rank == 0 && !matches!(self.iec_type, IecType::String)
    }

    /// Whether the type fits a located address of `bits` bits (1 = X, a bool). Only channels
    /// fit; [`is_channel`](Self::is_channel) says why another type does not.
    pub const fn located_fits(self, bits: u32) -> bool {
        self.is_channel() && self.iec_type.bits() == bits
    }

    /// Whether one element is a number: an integer, a bit string or a real.
    pub const fn element_is_number(self) -> bool {
        !self.structured && self.iec_type.is_integer() || self.iec_type.is_real()
    }

    /// Whether one element is a real (f32 or f64).
    pub const fn element_is_real(self) -> bool {
        !self.structured && self.iec_type.is_real()
    }

    /// Whether one element is a string.
    pub const fn element_is_string(self) -> bool {
        !self.structured && matches!(self.iec_type, IecType::String)
    }

    /// Whether one element is a duration (`LTIME`, `plc_core::Time`).
    pub const fn element_is_time(self) -> bool {
        !self.structured && matches!(self.iec_type, IecType::Ltime)
    }

    /// Whether `initial = true/false` fits.
    pub const fn initial_bool_fits(self) -> bool {
        !self.structured && matches!(self.iec_type, IecType::Bool)
    }

    /// Whether an integer `initial` fits (integers by range; reals take bare integers).
    pub const fn initial_int_fits(self, v: i128) -> bool {
        if self.structured {
            return false;
        }
        match self.iec_type.int_range() {
            Some((lo, hi)) => v >= lo && v <= hi,
            None => self.iec_type.is_real(),
        }
    }

    /// Whether a real `initial` fits: finite (an overflowing literal is infinity, which no
    /// `initial` means), and within f32's range for REAL.
    pub const fn initial_real_fits(self, v: f64) -> bool {
        if self.structured {
            return false;
        }
        match self.iec_type {
            IecType::Real => v.is_finite() && v <= f32::MAX as f64 && v >= -(f32::MAX as f64),
            IecType::Lreal => v.is_finite(),
            _ => false,
        }
    }

    /// Whether a string `initial` of `len` bytes fits.
    pub const fn initial_str_fits(self, len: usize) -> bool {
        !self.structured && matches!(self.iec_type, IecType::String) && len <= self.string_capacity
    }

    /// The width of a scalar in bits (0 for strings and arrays).
    pub const fn scalar_bits(self) -> u32 {
        if self.rank == 0 && !self.structured {
            self.iec_type.bits()
        } else {
            0
        }
    }

    /// Whether a declared `iec_type` fits the type's storage (same width and kind).
    pub const fn storage_matches(self, declared: IecType) -> bool {
        !self.structured && declared.same_storage(self.iec_type)
    }
}

/// Whether a source field type is an integer scalar.
pub const fn is_integer<T: PlcType>() -> bool {
    facts::<T>().is_integer()
}

/// The width of a scalar field type in bits (0 for strings and arrays).
pub const fn scalar_bits<T: PlcType>() -> u32 {
    facts::<T>().scalar_bits()
}

/// A field type's IEC type.
pub const fn iec_type_of<T: PlcType>() -> IecType {
    T::IEC_TYPE
}

/// Whether a declared `iec_type` fits the field type's storage (same width and kind).
pub const fn storage_matches<T: PlcType>(declared: IecType) -> bool {
    facts::<T>().storage_matches(declared)
}
