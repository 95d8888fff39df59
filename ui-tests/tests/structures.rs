//! Structured types: `#[derive(PlcStruct)]` fields of a `GlobalMemory`, alone, in arrays and
//! nested; their images, metadata, paths, bits, initial values and writes.

use plc_core::{Access, Direction, GlobalMemory, IecType, PlcStruct, PlcType, SetError, Value};
use zerocopy::IntoBytes;

/// One axis of the machine.
#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// Actual position in mm
    pub pos: f64,
    #[plc(initial = 250.0)]
    pub target: f64,
    #[plc(direction = "input")]
    pub enable: bool,
    #[plc(direction = "output", read_only)]
    pub fault: bool,
    pub state: u16,
    #[plc(source = "state", bit = 3)]
    pub homed: bool,
    #[plc(nonvolatile, initial = 7)]
    pub cycles: u32,
}

#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
#[plc(name = "Station")]
pub struct StationData {
    pub axes: [Axis; 2],
    pub count: i32,
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Gm {
    #[plc(initial = 5)]
    pub speed: i32,
    pub lift: Axis,
    pub axes: [Axis; 3],
    pub station: StationData,
    pub grid: [[u8; 3]; 2],
}

/// What a `#[repr(C)]` struct of the same members would hold, byte for byte.
#[repr(C, packed)]
#[derive(zerocopy::IntoBytes, zerocopy::Immutable, Clone, Copy)]
struct AxisRef {
    pos: f64,
    target: f64,
    enable: u8,
    fault: u8,
    state: u16,
    homed: u8,
    cycles: u32,
}

fn axis_ref(a: &Axis) -> AxisRef {
    AxisRef {
        pos: a.pos,
        target: a.target,
        enable: a.enable as u8,
        fault: a.fault as u8,
        state: a.state,
        homed: a.homed as u8,
        cycles: a.cycles,
    }
}

fn sample() -> Gm {
    let mut gm = Gm::default();
    gm.lift.pos = 12.5;
    gm.axes[1].state = 0x0F07;
    gm.axes[1].homed = true;
    gm.axes[2].enable = true;
    gm.station.axes[1].target = -3.0;
    gm.station.count = -9;
    gm.grid[1][2] = 42;
    gm.pack_bits();
    gm
}

#[test]
fn the_image_of_a_nested_declaration_is_the_concatenation_of_its_members_images() {
    let gm = sample();
    let mut expected = Vec::new();
    expected.extend_from_slice(&gm.speed.to_le_bytes());
    expected.extend_from_slice(axis_ref(&gm.lift).as_bytes());
    for a in &gm.axes {
        expected.extend_from_slice(axis_ref(a).as_bytes());
    }
    for a in &gm.station.axes {
        expected.extend_from_slice(axis_ref(a).as_bytes());
    }
    expected.extend_from_slice(&gm.station.count.to_le_bytes());
    expected.extend_from_slice(gm.grid.as_flattened());
    assert_eq!(gm.to_image().as_bytes(), &expected[..]);
    assert_eq!(core::mem::size_of::<<Axis as PlcType>::Repr>(), 25);
    assert_eq!(Gm::from_image(&gm.to_image()), gm);
}

#[test]
fn metadata_describes_members_and_their_types() {
    let lift = &Gm::VARIABLES[1];
    assert_eq!(lift.type_name(), "Axis");
    assert!(lift.is_structured());
    assert_eq!((lift.offset, lift.size), (4, 25));
    assert_eq!(lift.members().len(), 7);
    assert_eq!(lift.leaves(), 7);
    let axes = &Gm::VARIABLES[2];
    assert_eq!((axes.dims, axes.leaves()), (&[3usize][..], 21));
    let station = &Gm::VARIABLES[3];
    assert_eq!(station.type_name(), "Station");
    assert_eq!(station.members()[0].type_name(), "Axis");
    assert_eq!(station.leaves(), 15);
    let pos = &lift.members()[0];
    assert_eq!(
        (pos.name, pos.iec_type, pos.offset, pos.description),
        ("pos", IecType::Lreal, 0, "Actual position in mm")
    );
    let enable = &lift.members()[2];
    assert_eq!(enable.direction, Direction::Input);
    assert_eq!(lift.members()[3].access, Access::ReadOnly);
    assert_eq!(Gm::VARIABLES[0].type_name(), "DINT");
    assert_eq!(<StationData as PlcType>::DEPTH, 2);
}

#[test]
fn defaults_reach_every_member_and_element() {
    let gm = Gm::default();
    assert_eq!(gm.speed, 5);
    assert_eq!(gm.lift.target, 250.0);
    assert!(gm.axes.iter().all(|a| a.target == 250.0 && a.cycles == 7));
    assert!(gm.station.axes.iter().all(|a| a.cycles == 7));
    assert_eq!(Axis::default().target, 250.0);
}

#[test]
fn paths_find_every_basic_value() {
    let gm = sample();
    let at = Gm::find("axes[1].state").unwrap();
    assert_eq!((at.index, at.leaf), (2, 7 + 4));
    assert_eq!(gm.get_at(&at), Value::UInt(0x0F0F));
    assert_eq!(at.offset, 4 + 25 + 25 + 16 + 2);
    let deep = Gm::find("STATION.Axes[1].TARGET").unwrap();
    assert_eq!(gm.get_at(&deep), Value::Real(-3.0));
    assert_eq!(gm.get_at(&Gm::find("grid[1,2]").unwrap()), Value::UInt(42));
    assert_eq!(gm.get_at(&Gm::find("grid[5]").unwrap()), Value::UInt(42));
    assert_eq!(gm.get_at(&Gm::find("speed").unwrap()), Value::Int(5));
    // Bits mapped inside a structure follow their source.
    assert_eq!(
        gm.get_at(&Gm::find("axes[1].homed").unwrap()),
        Value::Bool(true)
    );
    for bad in [
        "axes[3].pos",
        "axes.pos",
        "axes[0]",
        "lift",
        "lift.nope",
        "speed.x",
        "grid[2,0]",
        "grid",
        "",
    ] {
        assert!(Gm::find(bad).is_none(), "{bad}");
    }
    assert_eq!(
        Gm::locate("lift.nope").unwrap_err().to_string(),
        "`lift` has no member `nope`"
    );
    assert_eq!(
        Gm::locate("axes.pos").unwrap_err().to_string(),
        "`axes` is an array: name one element, such as `axes[0]`"
    );
}

#[test]
fn set_at_reaches_members_with_their_checks_and_bits() {
    let mut gm = sample();
    let state = Gm::find("axes[0].state").unwrap();
    gm.set_at(&state, Value::UInt(0b1000)).unwrap();
    assert!(gm.axes[0].homed, "the bit-mapped bool follows its source");
    let homed = Gm::find("axes[0].homed").unwrap();
    gm.set_at(&homed, Value::Bool(false)).unwrap();
    assert_eq!(gm.axes[0].state, 0);
    let pos = Gm::find("station.axes[0].pos").unwrap();
    gm.set_at(&pos, Value::Real(1.25)).unwrap();
    assert_eq!(gm.station.axes[0].pos, 1.25);
    assert!(matches!(
        gm.set_at(&state, Value::Int(-1)),
        Err(SetError::Value { .. })
    ));
    // The same values through `set` and the leaf number, as the mailbox sends them.
    gm.set(2, 7 * 2, Value::Real(9.0)).unwrap();
    assert_eq!(gm.axes[2].pos, 9.0);
    assert_eq!(gm.try_get(2, 21), None);
    assert!(gm.set(2, 21, Value::Real(1.0)).is_err());
}

#[test]
fn tools_may_write_in_parameters_but_not_read_only_members() {
    assert!(Gm::find("lift.enable").unwrap().writable);
    assert!(!Gm::find("lift.fault").unwrap().writable);
    assert!(Gm::find("axes[2].pos").unwrap().writable);
}

#[test]
fn the_layout_hash_covers_the_structure() {
    #[derive(PlcStruct, Clone, Copy, Debug)]
    #[plc(name = "Axis")]
    pub struct Other {
        pub pos: f64,
        pub target: f64,
        pub enable: bool,
        pub fault: bool,
        pub state: u16,
        pub homed: bool,
        pub cycles_renamed: u32,
    }
    #[derive(GlobalMemory, Debug, Clone)]
    pub struct A {
        pub lift: Axis,
    }
    #[derive(GlobalMemory, Debug, Clone)]
    pub struct B {
        pub lift: Other,
    }
    assert_ne!(A::LAYOUT_HASH, B::LAYOUT_HASH);
}
