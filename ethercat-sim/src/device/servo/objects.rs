//! The AKD's CoE object dictionary: identity and communication objects, the PDO assignment
//! and mappings ethercrab reads by SDO, and the CiA 402 objects the drive model reads and
//! writes each cycle. Where each value comes from: `data/README.md` ("AKD").

use crate::coe::{ARRAY, Dictionary, READ, READ_WRITE, RECORD, RX_MAPPABLE, TX_MAPPABLE, deftype};

/// 0x6040 controlword (u16, RxPDO).
pub(crate) const CONTROLWORD: u16 = 0x6040;
/// 0x6041 statusword (u16, TxPDO).
pub(crate) const STATUSWORD: u16 = 0x6041;
/// 0x6060 modes of operation (i8, RxPDO).
pub(crate) const MODES_OF_OPERATION: u16 = 0x6060;
/// 0x6061 modes of operation display (i8, TxPDO).
pub(crate) const MODES_DISPLAY: u16 = 0x6061;
/// 0x6063 position actual internal value (i32): the AKD's fixed PDOs map it; with the
/// simulated 1:1 scaling it equals 0x6064.
pub(crate) const POSITION_INTERNAL: u16 = 0x6063;
/// 0x6064 position actual value (i32, increments, TxPDO).
pub(crate) const POSITION_ACTUAL: u16 = 0x6064;
/// 0x6065 following error window (u32, increments, SDO).
pub(crate) const FOLLOWING_ERROR_WINDOW: u16 = 0x6065;
/// 0x6066 following error time out (u16, ms, SDO).
pub(crate) const FOLLOWING_ERROR_TIME_OUT: u16 = 0x6066;
/// 0x606C velocity actual value (i32, increments/s, TxPDO).
pub(crate) const VELOCITY_ACTUAL: u16 = 0x606C;
/// 0x6077 torque actual value (i16, per mille of the peak torque).
pub(crate) const TORQUE_ACTUAL: u16 = 0x6077;
/// 0x607A target position (i32, increments, RxPDO).
pub(crate) const TARGET_POSITION: u16 = 0x607A;
/// 0x607C home offset (i32, increments, SDO).
pub(crate) const HOME_OFFSET: u16 = 0x607C;
/// 0x607F max profile velocity (u32, increments/s, SDO): the velocity limit.
pub(crate) const MAX_VELOCITY: u16 = 0x607F;
/// 0x6085 quick stop deceleration (u32, increments/s², SDO).
pub(crate) const QUICK_STOP_DECELERATION: u16 = 0x6085;
/// 0x6098 homing method (i8, SDO).
pub(crate) const HOMING_METHOD: u16 = 0x6098;
/// 0x60C5 max acceleration (u32, increments/s², SDO): the torque limit over the inertia.
pub(crate) const MAX_ACCELERATION: u16 = 0x60C5;
/// 0x60F4 following error actual value (i32, increments, TxPDO).
pub(crate) const FOLLOWING_ERROR_ACTUAL: u16 = 0x60F4;
/// 0x60FF target velocity (i32, increments/s, RxPDO).
pub(crate) const TARGET_VELOCITY: u16 = 0x60FF;
/// 0x603F error code (u16, TxPDO).
pub(crate) const ERROR_CODE: u16 = 0x603F;

/// Increments per motor revolution: the AKD's default feedback resolution, 2^20 (0x608F:01,
/// as ethercrab's AKD example reads it).
pub(crate) const INCREMENTS_PER_REV: u32 = 1 << 20;

/// The RxPDO mapping the simulated drive starts with in 0x1600: controlword, modes of
/// operation, target position, target velocity (mapping entries: index << 16 | sub << 8 |
/// bit length).
const RX_MAPPING: [u32; 4] = [0x6040_0010, 0x6060_0008, 0x607A_0020, 0x60FF_0020];
/// The TxPDO mapping in 0x1A00: statusword, modes display, position, velocity, following
/// error, error code.
const TX_MAPPING: [u32; 6] = [
    0x6041_0010,
    0x6061_0008,
    0x6064_0020,
    0x606C_0020,
    0x60F4_0020,
    0x603F_0010,
];
/// Entries each free mapping object (0x1600-0x1603, 0x1A00-0x1A03) has room for, so that a
/// program can map more objects by SDO (the real limit is not documented here: invented).
const MAPPING_ROOM: u8 = 8;

/// The dictionary of an AKD with identity `vendor`, `product`, `revision`, `serial` (its
/// EEPROM's). Communication objects first, then the drive profile.
pub(crate) fn akd(vendor: u32, product: u32, revision: u32, serial: u32) -> Dictionary {
    let mut d = Dictionary::default();
    // Device type: CiA 402 (0x192) servo (bit 17), what ethercrab's AKD example tests.
    d.set(0x1000, 0, 0x0002_0192, 4, false);
    d.text(0x1008, "AKD");
    // The firmware version ethercrab's AKD example names ("M_01-20-00-003").
    d.text(0x100A, "M_01-20-00-003");
    d.record(0x1018, &[vendor, product, revision, serial], 4, false);
    // SyncManager types: mailbox out, mailbox in, outputs, inputs (capture [R5]: 4 subs,
    // SM2 = 3).
    d.record(0x1C00, &[1, 2, 3, 4], 1, false);
    free_mappings(&mut d);
    fixed_mappings(&mut d);
    // PDO assignment: one PDO per direction (see `data/README.md`: preset, not the AKD's
    // power-on assignment); writable, with room for four PDOs as the real objects have.
    assignment(&mut d, 0x1C12, 0x1600);
    assignment(&mut d, 0x1C13, 0x1A00);
    profile(&mut d);
    descriptions(&mut d);
    d
}

/// The names and data types the SDO information service gives: CiA 402's object names and
/// data types for the drive profile (0x603F-0x60FF, 0x6502), CiA 301's for the communication
/// objects (0x1000-0x1018), ETG.1000.6's for the SyncManager objects (0x1C00-0x1C13); the
/// PDO mapping objects after CiA 301's "RPDO/TPDO mapping parameter". See `data/README.md`.
fn descriptions(d: &mut Dictionary) {
    use deftype::*;
    let (rx, tx) = (READ_WRITE | RX_MAPPABLE, READ | TX_MAPPABLE);
    // Entries of records and arrays without names of their own: "SubIndex 001" ...
    let sub_names = crate::coe::sub_names();
    let sub_name = |i: u8| sub_names[usize::from(i) - 1].as_str();
    d.describe_var(0x1000, "Device type", UNSIGNED32, 32, READ);
    d.describe_var(
        0x1008,
        "Manufacturer device name",
        VISIBLE_STRING,
        8 * 3,
        READ,
    );
    d.describe_var(
        0x100A,
        "Manufacturer software version",
        VISIBLE_STRING,
        8 * 14,
        READ,
    );
    let identity = [
        (1, "Vendor-ID", UNSIGNED32, 32, READ),
        (2, "Product code", UNSIGNED32, 32, READ),
        (3, "Revision number", UNSIGNED32, 32, READ),
        (4, "Serial number", UNSIGNED32, 32, READ),
    ];
    d.describe_record(0x1018, "Identity object", RECORD, IDENTITY, READ, &identity);
    let types: Vec<(u8, &str, u16, u16, u16)> = (1..=4u8)
        .map(|i| (i, sub_name(i), UNSIGNED8, 8, READ))
        .collect();
    d.describe_record(
        0x1C00,
        "Sync manager communication type",
        ARRAY,
        UNSIGNED8,
        READ,
        &types,
    );
    let assign: Vec<(u8, &str, u16, u16, u16)> = (1..=4u8)
        .map(|i| (i, sub_name(i), UNSIGNED16, 16, READ_WRITE))
        .collect();
    d.describe_record(
        0x1C12,
        "Sync manager 2 PDO assignment",
        ARRAY,
        UNSIGNED16,
        READ_WRITE,
        &assign,
    );
    d.describe_record(
        0x1C13,
        "Sync manager 3 PDO assignment",
        ARRAY,
        UNSIGNED16,
        READ_WRITE,
        &assign,
    );
    for (base, kind) in [
        (0x1600u16, "RPDO"),
        (0x1700, "RPDO"),
        (0x1A00, "TPDO"),
        (0x1B00, "TPDO"),
    ] {
        for offset in 0..0x100u16 {
            let index = base + offset;
            let subs: Vec<u8> = (1..=u8::MAX)
                .take_while(|&s| d.get(index, s).is_some())
                .collect();
            if subs.is_empty() {
                continue;
            }
            let access = if base & 0x0100 == 0 { READ_WRITE } else { READ };
            let entries: Vec<(u8, &str, u16, u16, u16)> = subs
                .iter()
                .map(|&s| (s, sub_name(s), UNSIGNED32, 32, access))
                .collect();
            let name = format!("{kind} mapping parameter {:#06x}", index);
            d.describe_record(index, &name, RECORD, PDO_MAPPING, access, &entries);
        }
    }
    // CiA 402 drive profile.
    let vars: [(u16, &str, u16, u16, u16); 21] = [
        (ERROR_CODE, "Error code", UNSIGNED16, 16, tx),
        (CONTROLWORD, "Controlword", UNSIGNED16, 16, rx),
        (STATUSWORD, "Statusword", UNSIGNED16, 16, tx),
        (0x605A, "Quick stop option code", INTEGER16, 16, READ),
        (MODES_OF_OPERATION, "Modes of operation", INTEGER8, 8, rx),
        (MODES_DISPLAY, "Modes of operation display", INTEGER8, 8, tx),
        (
            POSITION_INTERNAL,
            "Position actual internal value",
            INTEGER32,
            32,
            tx,
        ),
        (POSITION_ACTUAL, "Position actual value", INTEGER32, 32, tx),
        (
            FOLLOWING_ERROR_WINDOW,
            "Following error window",
            UNSIGNED32,
            32,
            READ_WRITE,
        ),
        (
            FOLLOWING_ERROR_TIME_OUT,
            "Following error time out",
            UNSIGNED16,
            16,
            READ_WRITE,
        ),
        (VELOCITY_ACTUAL, "Velocity actual value", INTEGER32, 32, tx),
        (TORQUE_ACTUAL, "Torque actual value", INTEGER16, 16, tx),
        (TARGET_POSITION, "Target position", INTEGER32, 32, rx),
        (HOME_OFFSET, "Home offset", INTEGER32, 32, READ_WRITE),
        (
            MAX_VELOCITY,
            "Max profile velocity",
            UNSIGNED32,
            32,
            READ_WRITE,
        ),
        (
            QUICK_STOP_DECELERATION,
            "Quick stop deceleration",
            UNSIGNED32,
            32,
            READ_WRITE,
        ),
        (HOMING_METHOD, "Homing method", INTEGER8, 8, READ_WRITE),
        (
            MAX_ACCELERATION,
            "Max acceleration",
            UNSIGNED32,
            32,
            READ_WRITE,
        ),
        (
            FOLLOWING_ERROR_ACTUAL,
            "Following error actual value",
            INTEGER32,
            32,
            tx,
        ),
        (TARGET_VELOCITY, "Target velocity", INTEGER32, 32, rx),
        (0x6502, "Supported drive modes", UNSIGNED32, 32, READ),
    ];
    for (index, name, ty, bits, access) in vars {
        d.describe_var(index, name, ty, bits, access);
    }
    let resolution = [
        (1, "Encoder increments", UNSIGNED32, 32, READ),
        (2, "Motor revolutions", UNSIGNED32, 32, READ),
    ];
    d.describe_record(
        0x608F,
        "Position encoder resolution",
        ARRAY,
        UNSIGNED32,
        READ,
        &resolution,
    );
    let period = [
        (
            1,
            "Interpolation time period value",
            UNSIGNED8,
            8,
            READ_WRITE,
        ),
        (2, "Interpolation time index", INTEGER8, 8, READ_WRITE),
    ];
    d.describe_record(
        0x60C2,
        "Interpolation time period",
        RECORD,
        0,
        READ,
        &period,
    );
}

/// 0x1600-0x1603 and 0x1A00-0x1A03, freely mappable: 0x1600/0x1A00 preset to the image
/// above, the others as capture [R5] shows them (controlword or statusword plus one object).
fn free_mappings(d: &mut Dictionary) {
    let rx: [&[u32]; 4] = [
        &RX_MAPPING,
        &[0x6040_0010, 0x6060_0008],
        &[0x6040_0010, 0x607A_0020],
        &[0x6040_0010, 0x60FF_0020],
    ];
    let tx: [&[u32]; 4] = [
        &TX_MAPPING,
        &[0x6041_0010, 0x6061_0008],
        &[0x6041_0010, 0x6064_0020],
        &[0x6041_0010, 0x606C_0020],
    ];
    for (base, maps) in [(0x1600u16, rx), (0x1A00, tx)] {
        for (i, map) in maps.iter().enumerate() {
            let index = base + i as u16;
            d.record(index, map, 4, true);
            for sub in map.len() as u8 + 1..=MAPPING_ROOM {
                d.set(index, sub, 0, 4, true);
            }
        }
    }
}

/// The AKD's fixed PDOs ethercrab's AKD example assigns (0x1702 velocity, 0x1B01 position
/// and statusword) and the position ones beside them, read-only, as the EEPROM's PDO
/// categories list them. Objects they map that the model lacks (0x60C1:01, 0x60B2, 0x60FD,
/// 0x3470:04) read as 0 and are ignored when written.
fn fixed_mappings(d: &mut Dictionary) {
    let fixed: [(u16, &[u32]); 6] = [
        (0x1701, &[0x60C1_0120, 0x6040_0010]),
        (0x1702, &[0x60FF_0020, 0x6040_0010]),
        (0x1724, &[0x607A_0020, 0x6040_0010, 0x60B2_0010]),
        (0x1B01, &[0x6063_0020, 0x6041_0010]),
        (0x1B24, &[0x6064_0020, 0x6041_0010]),
        (
            0x1B26,
            &[
                0x6041_0010,
                0x6064_0020,
                0x6077_0010,
                0x60FD_0020,
                0x3470_0410,
                0x60F4_0020,
            ],
        ),
    ];
    for (index, map) in fixed {
        d.record(index, map, 4, false);
    }
}

fn assignment(d: &mut Dictionary, index: u16, pdo: u16) {
    d.record(index, &[pdo as u32], 2, true);
    for sub in 2..=4 {
        d.set(index, sub, 0, 2, true);
    }
}

/// The CiA 402 objects. Limits and defaults are invented for a small servo (3000 rpm,
/// 2000 rev/s²) and say so in `data/README.md`.
fn profile(d: &mut Dictionary) {
    let rev = INCREMENTS_PER_REV;
    // (index, value, size, writable); process data objects are written by the MainDevice
    // through the PDOs (rx) or by the model (tx).
    let objects: [(u16, u32, u8, bool); 21] = [
        (CONTROLWORD, 0, 2, true),
        (STATUSWORD, 0, 2, false),
        (MODES_OF_OPERATION, 8, 1, true),
        (MODES_DISPLAY, 0, 1, false),
        (POSITION_INTERNAL, 0, 4, false),
        (POSITION_ACTUAL, 0, 4, false),
        (FOLLOWING_ERROR_WINDOW, rev, 4, true),
        (FOLLOWING_ERROR_TIME_OUT, 0, 2, true),
        (VELOCITY_ACTUAL, 0, 4, false),
        (TORQUE_ACTUAL, 0, 2, false),
        (TARGET_POSITION, 0, 4, true),
        (HOME_OFFSET, 0, 4, true),
        (MAX_VELOCITY, 50 * rev, 4, true),
        (QUICK_STOP_DECELERATION, 2000 * rev, 4, true),
        (HOMING_METHOD, 37, 1, true),
        (MAX_ACCELERATION, 2000 * rev, 4, true),
        (FOLLOWING_ERROR_ACTUAL, 0, 4, false),
        (TARGET_VELOCITY, 0, 4, true),
        (ERROR_CODE, 0, 2, false),
        // Supported drive modes: homing (bit 5), CSP (bit 7), CSV (bit 8).
        (0x6502, 1 << 5 | 1 << 7 | 1 << 8, 4, false),
        // Quick stop option code 2: stop on the quick stop ramp, then switch on disabled.
        (0x605A, 2, 2, false),
    ];
    for (index, value, size, writable) in objects {
        d.set(index, 0, value, size, writable);
    }
    // Feedback resolution: increments per revolution over motor revolutions.
    d.record(0x608F, &[rev, 1], 4, false);
    // Interpolation time period: 1 × 10^-3 s (the example computes its cycle from it).
    d.set(0x60C2, 0, 2, 1, false);
    d.set(0x60C2, 1, 1, 1, true);
    d.set(0x60C2, 2, (-3i8) as u8 as u32, 1, true);
}

/// Writes `value` into the existing entry `index`:`sub`, cut to its size; an object the
/// dictionary lacks is ignored (a PDO may map objects the model does not have).
pub(crate) fn store(d: &mut Dictionary, index: u16, sub: u8, value: u32) {
    if let Some(e) = d
        .entries
        .iter_mut()
        .find(|e| (e.index, e.sub) == (index, sub))
    {
        e.value = match e.size {
            1 => value & 0xFF,
            2 => value & 0xFFFF,
            _ => value,
        };
    }
}

/// Typed reads of sub-index 0 (0 for a missing object: the model never fails on one).
pub(crate) fn u16_of(d: &Dictionary, index: u16) -> u16 {
    d.get(index, 0).unwrap_or(0) as u16
}

/// An INTEGER8 object.
pub(crate) fn i8_of(d: &Dictionary, index: u16) -> i8 {
    d.get(index, 0).unwrap_or(0) as u8 as i8
}

/// An INTEGER32 object.
pub(crate) fn i32_of(d: &Dictionary, index: u16) -> i32 {
    d.get(index, 0).unwrap_or(0) as i32
}

/// An UNSIGNED32 object.
pub(crate) fn u32_of(d: &Dictionary, index: u16) -> u32 {
    d.get(index, 0).unwrap_or(0)
}
