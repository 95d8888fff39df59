//! The `GlobalMemory` trait that `#[derive(GlobalMemory)]` implements, and the metadata it
//! publishes about every variable.

use crate::{IecType, ProcessImage, ProcessImageError, Value, ValueError};
use core::fmt;
use zerocopy::{FromBytes, Immutable, IntoBytes, KnownLayout, Unaligned};

pub use plc_rules::{Access, Direction};

/// A bool mapped onto one bit of an integer variable (the JSON variable-list format: `source` and `bit`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BitMapping {
    /// Index of the source variable in [`GlobalMemory::VARIABLES`].
    pub source: usize,
    /// Bit in the source, 0 = least significant.
    pub bit: u8,
}

/// A bus description compiled into a program: `#[plc(bus = "bus/machine.toml")]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BusSource {
    /// The path as the attribute wrote it (relative to the crate's directory).
    pub file: &'static str,
    /// The file's text when the program was compiled.
    pub text: &'static str,
}

/// Everything a tool needs to know about one variable: its name, type, place in the image,
/// links and attributes. The derive builds one per field, in declaration order.
///
/// ```
/// use plc_core::{GlobalMemory, Direction};
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     /// Press force in kN
///     #[plc(direction = "input", at = "%ID0")]
///     force: f32,
///     #[plc(initial = 12, read_only)]
///     count: u16,
/// }
/// let v = &Gm::VARIABLES[0];
/// assert_eq!((v.name, v.iec_type.name(), v.offset, v.size), ("force", "REAL", 0, 4));
/// assert_eq!((v.description, v.address, v.direction), ("Press force in kN", Some("%ID0"), Direction::Input));
/// assert_eq!(Gm::VARIABLES[1].initial, Some("12"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct VarInfo {
    /// Symbol name: `#[plc(name = "...")]` or the field name.
    pub name: &'static str,
    /// IEC type (for arrays: of one element). For a structured variable (one with
    /// [`members`](Self::members)) it is `BYTE`, the unit its image is made of: see
    /// [`type_name`](Self::type_name) for its type.
    pub iec_type: IecType,
    /// The field's Rust type as written, e.g. `"[[f32; 4]; 3]"`.
    pub rust_type: &'static str,
    /// Byte offset in the image.
    pub offset: usize,
    /// Bytes in the image (all elements of an array).
    pub size: usize,
    /// Array dimensions, outermost first; empty for a scalar.
    pub dims: &'static [usize],
    /// The source word, for a bit-mapped bool.
    pub bit: Option<BitMapping>,
    /// `link = "ethercat.<device>.<entry>"`.
    pub link: Option<&'static str>,
    /// `at = "%IW4"`, as written.
    pub address: Option<&'static str>,
    /// `description = "..."` or the doc comment; `""` if none.
    pub description: &'static str,
    /// The initial value as JSON text (`12.5`, `true`, `"TEST-001"`), if declared.
    pub initial: Option<&'static str>,
    /// `nonvolatile` (alias `retain`): survives restarts.
    pub nonvolatile: bool,
    /// Whether tools may write it.
    pub access: Access,
    /// Where its value comes from.
    pub direction: Direction,
    /// `ux`: meant for an operator UI (the framework's web UI shows it).
    pub ux: bool,
    /// `quantity = "force"`: the physical quantity a display uses to pick units.
    pub quantity: Option<&'static str>,
    /// `unit = "mm"`: the engineering unit of the value (numbers only), as tools show it
    /// beside the value; a Sparkplug B metric's `engUnit`.
    pub unit: Option<&'static str>,
    /// `deadband = 0.5`: the reporting deadband, how far the value must move from the value
    /// last published before a publisher (the Sparkplug B edge node) sends a change again; in
    /// the variable's unit, 0 or more (numbers only). `None`: the publisher's default. Not a
    /// limit alarm's deadband, which is `alarm(deadband = ...)`.
    pub deadband: Option<f64>,
    pub(crate) members: &'static [VarInfo],
    pub(crate) struct_name: Option<&'static str>,
}

impl VarInfo {
    /// A structured variable's members (one element's, for an array of structures), with
    /// offsets from the structure's start; empty for a basic variable.
    pub const fn members(&self) -> &'static [VarInfo] {
        self.members
    }

    /// The name of its type: the structure's (`"Axis"`, `"TON"`) for a structured variable,
    /// else the IEC type's (`"UINT"`).
    pub const fn type_name(&self) -> &'static str {
        match self.struct_name {
            Some(name) => name,
            None => self.iec_type.name(),
        }
    }

    /// Whether it is a structure or an array of structures.
    pub const fn is_structured(&self) -> bool {
        self.struct_name.is_some()
    }

    /// Basic values it holds (see [`PlcType::LEAVES`](crate::PlcType::LEAVES)): its elements
    /// for a basic variable, times its members' basic values for a structured one.
    pub fn leaves(&self) -> usize {
        plc_rules::path::leaves(self)
    }

    /// Number of elements: the product of the dimensions, 1 for a scalar.
    pub const fn elements(&self) -> usize {
        plc_rules::access::elements(self.dims)
    }

    /// Bytes of one element (0 for an array without items, which the derive refuses).
    pub const fn element_size(&self) -> usize {
        plc_rules::access::element_size(self.size, self.dims)
    }

    /// Capacity in bytes of a `STRING` element (0 for other types).
    pub const fn string_capacity(&self) -> usize {
        plc_rules::access::string_capacity(self.iec_type, self.size, self.dims)
    }

    /// Whether tools may write it: read-write and neither an input nor a status.
    pub const fn writable_from_outside(&self) -> bool {
        plc_rules::access::writable_from_outside(self.access, self.direction)
    }
}

impl plc_rules::path::Node for VarInfo {
    fn name(&self) -> &str {
        self.name
    }
    fn dims(&self) -> &[usize] {
        self.dims
    }
    fn offset(&self) -> usize {
        self.offset
    }
    fn size(&self) -> usize {
        self.size
    }
    fn members(&self) -> &[VarInfo] {
        self.members
    }
    fn access(&self) -> Access {
        self.access
    }
    fn direction(&self) -> Direction {
        self.direction
    }
}

/// One basic value of a program's variables, found by its path with
/// [`GlobalMemory::find`]: a scalar, one element of an array, or one such inside a structure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Location {
    /// Index of the top-level variable in [`GlobalMemory::VARIABLES`].
    pub index: usize,
    /// The value's number among that variable's basic values (its element for a basic array;
    /// see [`PlcType::LEAVES`](crate::PlcType::LEAVES)), as `get` and `set` take it.
    pub leaf: usize,
    /// The basic variable or member that holds the value.
    pub var: &'static VarInfo,
    /// The element within `var` (0 for a scalar).
    pub element: usize,
    /// Byte offset of the value in the image.
    pub offset: usize,
    /// Whether tools may write it: the variable and every member on the way are writable
    /// (inside a structure, IN parameters are).
    pub writable: bool,
}

/// The layout hash of a variable list (see [`plc_rules::layout`]); the derive sets
/// [`GlobalMemory::LAYOUT_HASH`] to this, computed at compile time.
pub const fn layout_hash(vars: &[VarInfo]) -> u64 {
    hash_vars(plc_rules::layout::LayoutHasher::new(), vars).finish()
}

/// Each variable; a structured one's type name and then its members, recursively.
const fn hash_vars(
    h: plc_rules::layout::LayoutHasher,
    vars: &[VarInfo],
) -> plc_rules::layout::LayoutHasher {
    hash_range(h, vars, 0, vars.len())
}

/// [`layout_hash`] of a large declaration in parts: variables `start..end` of `vars` fed to
/// `h`. The derive gives each part a `const` of its own, so that no one const evaluation
/// runs into the compiler's guard against endless loops (100,000 variables did).
#[doc(hidden)]
pub const fn hash_range(
    mut h: plc_rules::layout::LayoutHasher,
    vars: &[VarInfo],
    start: usize,
    end: usize,
) -> plc_rules::layout::LayoutHasher {
    let mut i = start;
    while i < end {
        let v = &vars[i];
        let bit = match v.bit {
            Some(b) => Some((b.source, b.bit)),
            None => None,
        };
        h = h.var(v.name, v.iec_type.name(), v.offset, v.size, v.dims, bit);
        if let Some(name) = v.struct_name {
            h = hash_vars(
                h.bytes(b"struct\0").bytes(name.as_bytes()).bytes(&[0]),
                v.members,
            )
            .bytes(b"end\0");
        }
        i += 1;
    }
    h
}

/// Why [`GlobalMemory::set`] refused a value. Nothing was changed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetError {
    /// No variable has this index.
    UnknownIndex {
        /// The index given.
        index: usize,
    },
    /// The element index is beyond the array.
    ElementOutOfRange {
        /// The variable.
        name: &'static str,
        /// The element index given.
        element: usize,
        /// The number of elements.
        len: usize,
    },
    /// The value does not fit the variable.
    Value {
        /// The variable.
        name: &'static str,
        /// What is wrong.
        error: ValueError,
    },
}

impl fmt::Display for SetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SetError::UnknownIndex { index } => write!(f, "no variable has index {index}"),
            SetError::ElementOutOfRange { name, element, len } => write!(
                f,
                "`{name}` has {len} elements: element {element} is out of range 0..{len}"
            ),
            SetError::Value { name, error } => write!(f, "`{name}`: {error}"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for SetError {}

/// The variables of a control program: implemented by `#[derive(GlobalMemory)]` on a struct
/// with named fields.
///
/// The derive also implements `Default` from the `initial` values (then packs bit-mapped bools
/// into their source words), so do not derive `Default` yourself.
///
/// ```
/// use plc_core::{GlobalMemory, Value};
/// #[derive(GlobalMemory, Debug, Clone, PartialEq)]
/// pub struct Gm {
///     #[plc(link = "ethercat.impact67_0.digital_inputs", direction = "input")]
///     pub impact67_0_digital_inputs: u16,
///     #[plc(source = "impact67_0_digital_inputs", bit = 1)]
///     pub ls_centering_pos: bool,
///     #[plc(initial = 1500, direction = "command")]
///     pub speed: i32,
/// }
/// let mut gm = Gm::default();
/// gm.impact67_0_digital_inputs = 0b10;
/// gm.unpack_bits();
/// assert!(gm.ls_centering_pos);
/// let i = Gm::index_of("SPEED").unwrap();
/// gm.set(i, 0, Value::Int(1200)).unwrap();
/// assert_eq!(gm.get(i, 0), Value::Int(1200));
/// assert_eq!(Gm::from_image(&gm.to_image()), gm);
/// ```
pub trait GlobalMemory: Sized {
    /// The shared-memory image: `#[repr(C)]`, alignment 1, no padding, each variable's bytes
    /// at its [`VarInfo::offset`], in declaration order; bools as `u8`, numbers little endian,
    /// strings `FixedString<N>`. The derive makes it one byte array: the bytes are those of a
    /// `#[repr(C)]` struct with one such field per variable, without that struct's compile
    /// time.
    type Image: FromBytes + IntoBytes + KnownLayout + Immutable + Unaligned + Copy + Send + 'static;

    /// One entry per field, in declaration order.
    const VARIABLES: &'static [VarInfo];

    /// [`layout_hash`] of [`VARIABLES`](Self::VARIABLES).
    const LAYOUT_HASH: u64;

    /// The declared alarms (`#[plc(alarm = "...")]`), one per watched basic value, in
    /// declaration order: an array of bools has one per element, a structure's member one per
    /// instance. Empty unless the derive says otherwise, so impls written by hand need not
    /// name it. See [`alarm`](crate::alarm).
    const ALARMS: &'static [crate::alarm::AlarmDecl] = &[];

    /// The bus description the struct was checked against (`#[plc(bus = "...")]`), if it
    /// names one: a program built as a module hands it to its host, which runs that bus
    /// unless told otherwise.
    const BUS: Option<BusSource> = None;

    /// Copies each bit-mapped bool out of its source word (the JSON variable-list format: after reading inputs).
    fn unpack_bits(&mut self);

    /// Copies each bit-mapped bool into its source word, keeping unmapped bits (the JSON variable-list format:
    /// before writing outputs).
    fn pack_bits(&mut self);

    /// The image of the current values.
    fn to_image(&self) -> Self::Image;

    /// Values from an image (any byte of a bool that is not 0 is `true`).
    fn from_image(image: &Self::Image) -> Self;

    /// Copies all values of `image` into `self` without building a new struct (the cycle's path).
    fn load_image(&mut self, image: &Self::Image) {
        *self = Self::from_image(image);
    }

    /// Writes the image of the current values into `image` (the cycle's path).
    fn store_image(&self, image: &mut Self::Image) {
        *image = self.to_image();
    }

    /// Index in [`VARIABLES`](Self::VARIABLES) of the variable with this symbol name, compared
    /// case-insensitively (the variable-editor rules).
    fn index_of(name: &str) -> Option<usize> {
        Self::VARIABLES
            .iter()
            .position(|v| v.name.eq_ignore_ascii_case(name))
    }

    /// The basic value a path names (`speed`, `grid[1,2]`, the flat `grid[5]`,
    /// `axes[1].pos`; names case-insensitive, indexes 0-based), or `None`. See
    /// [`locate`](Self::locate) for why a path names nothing.
    fn find(path: &str) -> Option<Location> {
        Self::locate(path).ok()
    }

    /// [`find`](Self::find), or what is wrong with the path.
    fn locate(path: &str) -> Result<Location, plc_rules::path::LocateError<'_>> {
        let f = plc_rules::path::locate(Self::VARIABLES, path)?;
        Ok(Location {
            index: f.index,
            leaf: f.leaf,
            var: f.node,
            element: f.element,
            offset: f.offset,
            writable: f.writable,
        })
    }

    /// The value at a [`Location`] of this program's variables.
    ///
    /// # Panics
    /// If the location is not one of this type's (found by another type's `find`).
    fn get_at(&self, at: &Location) -> Value {
        self.get(at.index, at.leaf)
    }

    /// Sets the value at a [`Location`], with the checks of [`set`](Self::set).
    fn set_at(&mut self, at: &Location, value: Value) -> Result<(), SetError> {
        self.set(at.index, at.leaf, value)
    }

    /// The value of element `element` (row-major; 0 for a scalar; for a structured variable
    /// the basic value numbered `element`, see [`Location::leaf`]) of variable `index`, or
    /// `None` if either index is out of range.
    fn try_get(&self, index: usize, element: usize) -> Option<Value>;

    /// The value of element `element` of variable `index`.
    ///
    /// # Panics
    /// If `index` or `element` is out of range, like slice indexing; see
    /// [`try_get`](Self::try_get).
    fn get(&self, index: usize, element: usize) -> Value {
        match self.try_get(index, element) {
            Some(v) => v,
            None => panic!("GlobalMemory::get: no variable {index} element {element}"),
        }
    }

    /// Sets element `element` of variable `index`, checking kind, range and string capacity.
    /// A bit-mapped bool also updates its source word's bit, and a source word also updates its
    /// bit-mapped bools. Access and direction are not checked here: they are enforced where
    /// writes come from outside (the mailbox, `plc set`).
    fn set(&mut self, index: usize, element: usize, value: Value) -> Result<(), SetError>;

    /// Gives `each` every place in this struct that a [`set`](Self::set) of element
    /// `element` of variable `index` writes: where the value lies (found through
    /// the compiler's field offsets by the derive, through structures and arrays), and for a
    /// bit-mapped bool its bit of the source word, for a source word its bools. A force
    /// captures the bytes there once ([`place::capture`](crate::place::capture)) and writes
    /// them at each of the cycle's boundaries instead of calling `set`.
    ///
    /// `false` if there is no such value or the type does not say where it lies: what an impl
    /// written by hand answers unless it overrides this, which it cannot do without `unsafe`
    /// (a [`StructPlace`](crate::place::StructPlace) is made only through `unsafe`
    /// constructors); callers then use `set`.
    ///
    /// ```
    /// use plc_core::{GlobalMemory, PlcStruct};
    /// #[derive(PlcStruct, Debug, Clone)]
    /// struct Axis {
    ///     enable: bool,
    ///     position: f64,
    /// }
    /// #[derive(GlobalMemory, Debug, Clone)]
    /// struct Gm {
    ///     count: u16,
    ///     axes: [Axis; 2],
    /// }
    /// let mut places = Vec::new();
    /// // `axes[1].position`: leaf 3 of `axes`.
    /// assert!(Gm::struct_places(1, 3, &mut |p| places.push(p)));
    /// let at = core::mem::offset_of!(Gm, axes)
    ///     + core::mem::size_of::<Axis>()
    ///     + core::mem::offset_of!(Axis, position);
    /// assert_eq!((places[0].offset(), places[0].len()), (at, 8));
    /// assert!(!Gm::struct_places(1, 4, &mut |_| {}), "`axes` has 4 basic values");
    /// ```
    fn struct_places(
        index: usize,
        element: usize,
        each: &mut dyn FnMut(crate::place::StructPlace<Self>),
    ) -> bool {
        let _ = (index, element, each);
        false
    }

    /// Reads every `at = "%I.."` variable from an input process image.
    fn read_inputs<B: AsRef<[u8]>>(
        &mut self,
        inputs: &ProcessImage<B>,
    ) -> Result<(), ProcessImageError>;

    /// Writes every `at = "%Q.."` variable into an output process image.
    fn write_outputs<B: AsRef<[u8]> + AsMut<[u8]>>(
        &self,
        outputs: &mut ProcessImage<B>,
    ) -> Result<(), ProcessImageError>;
}
