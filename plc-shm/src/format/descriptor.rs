//! The layout descriptor: every variable's metadata as JSON inside the segment, so tools read
//! and write a running program's variables without its Rust types.

use super::alarm_descriptor::AlarmDescriptor;
use plc_core::{Access, Direction, IecType, VarInfo};
use plc_rules::layout::LayoutHasher;
use serde::{Deserialize, Serialize};

/// One variable, owned: the fields of [`plc_core::VarInfo`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VarDescriptor {
    /// Symbol name.
    pub name: String,
    /// IEC type of one element.
    pub iec_type: IecType,
    /// The Rust type as written.
    pub rust_type: String,
    /// Byte offset in the image.
    pub offset: usize,
    /// Bytes in the image.
    pub size: usize,
    /// Array dimensions (empty for a scalar).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub dims: Vec<usize>,
    /// Source variable index and bit, for a bit-mapped bool.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bit: Option<BitDescriptor>,
    /// `ethercat.<device>.<entry>`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub link: Option<String>,
    /// IEC address, e.g. `%IW4`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub address: Option<String>,
    /// Description ("" if none).
    #[serde(default)]
    pub description: String,
    /// Initial value as JSON text.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial: Option<String>,
    /// Kept across restarts.
    #[serde(default)]
    pub nonvolatile: bool,
    /// Read-write or read-only for tools.
    pub access: Access,
    /// Input, output, command, status or internal.
    pub direction: Direction,
    /// Meant for an operator UI.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub ux: bool,
    /// The physical quantity a display uses to pick units (`"force"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub quantity: Option<String>,
    /// The engineering unit of the value (`"mm"`), for numbers.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unit: Option<String>,
    /// The reporting deadband: how far the value must move before a publisher sends a change
    /// (`None`: the publisher's default).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub deadband: Option<f64>,
    /// A structured variable's type name (`"Axis"`, `"TON"`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub type_name: Option<String>,
    /// A structured variable's members (one element's, for an array of structures), offsets
    /// from the structure's start.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub members: Vec<VarDescriptor>,
}

/// A bit-mapped bool's source.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct BitDescriptor {
    /// Index of the source variable.
    pub source: usize,
    /// Bit in the source, 0 = least significant.
    pub bit: u8,
}

/// The same answers as [`VarInfo`]'s, from the same helpers.
impl VarDescriptor {
    /// A scalar of type `iec_type`, `size` bytes at `offset`, with every attribute at its
    /// default (internal, read-write; no bit mapping, link, address, description, initial
    /// value, quantity, unit or deadband): for tools and tests that describe a variable
    /// without a program's Rust type. Set the rest with struct update syntax.
    ///
    /// ```
    /// use plc_core::IecType;
    /// use plc_shm::VarDescriptor;
    /// let force = VarDescriptor {
    ///     unit: Some("kN".into()),
    ///     ..VarDescriptor::basic("force", IecType::Real, 0, 4)
    /// };
    /// assert_eq!((force.rust_type.as_str(), force.deadband), ("f32", None));
    /// ```
    pub fn basic(name: &str, iec_type: IecType, offset: usize, size: usize) -> VarDescriptor {
        VarDescriptor {
            name: name.to_string(),
            iec_type,
            rust_type: iec_type.rust_name().to_string(),
            offset,
            size,
            dims: Vec::new(),
            bit: None,
            link: None,
            address: None,
            description: String::new(),
            initial: None,
            nonvolatile: false,
            access: Access::ReadWrite,
            direction: Direction::Internal,
            ux: false,
            quantity: None,
            unit: None,
            deadband: None,
            type_name: None,
            members: Vec::new(),
        }
    }

    /// Number of elements (1 for a scalar). Saturating: a damaged descriptor must not overflow
    /// (`check_variables` refuses it).
    pub fn elements(&self) -> usize {
        plc_rules::access::elements(&self.dims)
    }

    /// Bytes of one element (0 for a damaged descriptor with no elements).
    pub fn element_size(&self) -> usize {
        plc_rules::access::element_size(self.size, &self.dims)
    }

    /// Capacity of a string element in bytes (0 for other types).
    pub fn string_capacity(&self) -> usize {
        plc_rules::access::string_capacity(self.iec_type, self.size, &self.dims)
    }

    /// Whether tools may write it (read-write, neither input nor status).
    pub fn writable_from_outside(&self) -> bool {
        plc_rules::access::writable_from_outside(self.access, self.direction)
    }

    /// The type as tools show it: the structure's name, else the IEC type's.
    pub fn type_name(&self) -> &str {
        self.type_name
            .as_deref()
            .unwrap_or_else(|| self.iec_type.name())
    }
}

impl plc_core::write::Target for VarDescriptor {
    fn iec_type(&self) -> IecType {
        self.iec_type
    }

    fn string_capacity(&self) -> usize {
        VarDescriptor::string_capacity(self)
    }
}

impl plc_rules::path::Node for VarDescriptor {
    fn name(&self) -> &str {
        &self.name
    }
    fn dims(&self) -> &[usize] {
        &self.dims
    }
    fn offset(&self) -> usize {
        self.offset
    }
    fn size(&self) -> usize {
        self.size
    }
    fn members(&self) -> &[VarDescriptor] {
        &self.members
    }
    fn access(&self) -> Access {
        self.access
    }
    fn direction(&self) -> Direction {
        self.direction
    }
}

impl From<&VarInfo> for VarDescriptor {
    fn from(v: &VarInfo) -> Self {
        VarDescriptor {
            name: v.name.to_string(),
            iec_type: v.iec_type,
            rust_type: v.rust_type.to_string(),
            offset: v.offset,
            size: v.size,
            dims: v.dims.to_vec(),
            bit: v.bit.map(|b| BitDescriptor {
                source: b.source,
                bit: b.bit,
            }),
            link: v.link.map(str::to_string),
            address: v.address.map(str::to_string),
            description: v.description.to_string(),
            initial: v.initial.map(str::to_string),
            nonvolatile: v.nonvolatile,
            access: v.access,
            direction: v.direction,
            ux: v.ux,
            quantity: v.quantity.map(str::to_string),
            unit: v.unit.map(str::to_string),
            deadband: v.deadband,
            type_name: v.is_structured().then(|| v.type_name().to_string()),
            members: v.members().iter().map(VarDescriptor::from).collect(),
        }
    }
}

/// All variables of a program, as stored in its segment.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LayoutDescriptor {
    /// Segment format version.
    pub format_version: u32,
    /// The layout hash the program was compiled with.
    pub layout_hash: u64,
    /// Size of the image in bytes.
    pub image_size: usize,
    /// The variables in declaration order.
    pub variables: Vec<VarDescriptor>,
    /// The program's alarms, in the order of the segment's alarm table.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub alarms: Vec<AlarmDescriptor>,
    /// Where the program keeps its alarm history (`plc alarms --history` reads it), if it
    /// keeps one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alarm_journal: Option<String>,
    /// How many records that journal keeps.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alarm_journal_capacity: Option<usize>,
}

impl LayoutDescriptor {
    /// The descriptor of a compiled `GlobalMemory` type.
    pub fn of<T: plc_core::GlobalMemory>() -> Self {
        LayoutDescriptor::of_schema(&plc_core::memory::Schema::of::<T>())
    }

    /// The descriptor of a program's variables as a runtime sees them (a compiled program's,
    /// or a loaded module's).
    pub fn of_schema(schema: &plc_core::memory::Schema) -> Self {
        LayoutDescriptor {
            format_version: plc_rules::layout::FORMAT_VERSION,
            layout_hash: schema.layout_hash,
            image_size: schema.image_size,
            variables: schema.variables.iter().map(VarDescriptor::from).collect(),
            alarms: AlarmDescriptor::all(schema.variables, schema.alarms),
            alarm_journal: None,
            alarm_journal_capacity: None,
        }
    }

    /// The layout hash recomputed from the variables (plc_rules::layout's recipe).
    pub fn computed_hash(&self) -> u64 {
        fn hash(mut h: LayoutHasher, vars: &[VarDescriptor]) -> LayoutHasher {
            for v in vars {
                let bit = v.bit.map(|b| (b.source, b.bit));
                h = h.var(&v.name, v.iec_type.name(), v.offset, v.size, &v.dims, bit);
                if let Some(name) = &v.type_name {
                    h = hash(
                        h.bytes(b"struct\0").bytes(name.as_bytes()).bytes(&[0]),
                        &v.members,
                    )
                    .bytes(b"end\0");
                }
            }
            h
        }
        hash(LayoutHasher::new(), &self.variables).finish()
    }

    /// Checks that every variable lies inside an image of `image_size` bytes, its size is a
    /// whole number of elements, and its bit mapping names a variable: a descriptor read from
    /// another process is not trusted to be what a compiler produced.
    pub fn check_variables(&self) -> Result<(), String> {
        let mut budget = MAX_NODES;
        check_level(&self.variables, self.image_size, 0, &mut budget)
    }
}

/// Most variables and members, all levels together, a descriptor may hold: far above any real
/// program, and a bound on the work a hostile one can cause.
const MAX_NODES: usize = 1 << 20;

/// Checks one level: each variable inside `space` bytes (the image, or one element of the
/// structure it belongs to), whole elements, bit mappings within the level, members within
/// their element, at most 8 levels.
fn check_level(
    vars: &[VarDescriptor],
    space: usize,
    depth: usize,
    budget: &mut usize,
) -> Result<(), String> {
    if depth > plc_rules::capacity::MAX_STRUCT_DEPTH {
        return Err(format!(
            "structures nest more than {} levels deep",
            plc_rules::capacity::MAX_STRUCT_DEPTH
        ));
    }
    *budget = budget
        .checked_sub(vars.len())
        .ok_or_else(|| format!("more than {MAX_NODES} variables and members"))?;
    let n_vars = vars.len();
    {
        for v in vars {
            let at = || {
                format!(
                    "variable `{}` (offset {}, {} bytes)",
                    v.name, v.offset, v.size
                )
            };
            if v.offset.checked_add(v.size).is_none_or(|end| end > space) {
                let whole = if depth == 0 {
                    "the image"
                } else {
                    "one element of its structure"
                };
                return Err(format!("{} lies outside {whole} of {space} bytes", at()));
            }
            let whole = match v.dims.iter().try_fold(1usize, |n, &d| n.checked_mul(d)) {
                Some(0) => v.size == 0,
                Some(n) => v.size.is_multiple_of(n),
                None => false,
            };
            if !whole {
                return Err(format!(
                    "{} is not a whole number of elements of dims {:?}",
                    at(),
                    v.dims
                ));
            }
            if let Some(b) = v.bit
                && (b.source >= n_vars || b.bit >= 64)
            {
                return Err(format!(
                    "{} maps bit {} of variable {}, which does not exist",
                    at(),
                    b.bit,
                    b.source
                ));
            }
            if v.type_name.is_some() == v.members.is_empty() {
                return Err(format!(
                    "{} has a type name without members or the reverse",
                    at()
                ));
            }
            if !v.members.is_empty() {
                check_level(&v.members, v.element_size(), depth + 1, budget)
                    .map_err(|e| format!("in `{}`: {e}", v.name))?;
            }
        }
    }
    Ok(())
}

impl LayoutDescriptor {
    /// Index of a variable by name, case-insensitively (the variable-editor rules).
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.variables
            .iter()
            .position(|v| v.name.eq_ignore_ascii_case(name))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn var(name: &str, offset: usize, size: usize) -> VarDescriptor {
        VarDescriptor::basic(name, IecType::Udint, offset, size)
    }

    fn structure(name: &str, offset: usize, members: Vec<VarDescriptor>) -> VarDescriptor {
        let size = members.iter().map(|m| m.offset + m.size).max().unwrap_or(0);
        VarDescriptor {
            iec_type: IecType::Byte,
            type_name: Some("S".into()),
            members,
            ..var(name, offset, size)
        }
    }

    fn descriptor(variables: Vec<VarDescriptor>, image_size: usize) -> LayoutDescriptor {
        LayoutDescriptor {
            format_version: plc_rules::layout::FORMAT_VERSION,
            layout_hash: 0,
            image_size,
            alarms: Vec::new(),
            alarm_journal: None,
            alarm_journal_capacity: None,
            variables,
        }
    }

    #[test]
    fn a_structure_s_members_must_lie_inside_one_element_and_nest_at_most_8_deep() {
        let good = structure("s", 0, vec![var("a", 0, 4), var("b", 4, 4)]);
        assert_eq!(descriptor(vec![good.clone()], 8).check_variables(), Ok(()));

        let mut outside = good.clone();
        outside.members[1].offset = 6;
        let e = descriptor(vec![outside], 8).check_variables().unwrap_err();
        assert!(
            e.contains("in `s`") && e.contains("one element of its structure"),
            "{e}"
        );

        let mut nameless = good.clone();
        nameless.type_name = None;
        let e = descriptor(vec![nameless], 8).check_variables().unwrap_err();
        assert!(e.contains("type name"), "{e}");

        let mut deep = var("leaf", 0, 4);
        for level in 0..9 {
            deep = structure(&format!("l{level}"), 0, vec![deep]);
        }
        let e = descriptor(vec![deep.clone()], 4)
            .check_variables()
            .unwrap_err();
        assert!(e.contains("more than 8 levels"), "{e}");
        // Eight levels are fine.
        let eight = deep.members.remove(0);
        assert_eq!(descriptor(vec![eight], 4).check_variables(), Ok(()));
    }

    #[test]
    fn the_hash_covers_members_and_type_names() {
        let a = descriptor(vec![structure("s", 0, vec![var("a", 0, 4)])], 4);
        let mut b = a.clone();
        b.variables[0].members[0].name = "b".into();
        let mut c = a.clone();
        c.variables[0].type_name = Some("T".into());
        assert_ne!(a.computed_hash(), b.computed_hash());
        assert_ne!(a.computed_hash(), c.computed_hash());
    }

    #[test]
    fn unit_and_deadband_are_written_only_where_declared_and_read_back() {
        let mut force = var("force", 0, 4);
        force.unit = Some("kN".into());
        force.deadband = Some(0.5);
        let plain = var("count", 4, 4);
        let json = serde_json::to_string(&descriptor(vec![force, plain], 8)).unwrap();
        assert!(json.contains(r#""unit":"kN","deadband":0.5"#), "{json}");
        assert_eq!(json.matches("unit").count(), 1, "{json}");
        let back: LayoutDescriptor = serde_json::from_str(&json).unwrap();
        assert_eq!(back.variables[0].unit.as_deref(), Some("kN"));
        assert_eq!(back.variables[0].deadband, Some(0.5));
        assert_eq!(
            (&back.variables[1].unit, back.variables[1].deadband),
            (&None, None)
        );
    }
}
