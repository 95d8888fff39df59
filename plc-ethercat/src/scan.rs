//! Scanning a bus for commissioning (`plc bus scan`): ethercrab brings the SubDevices to
//! PRE-OP, the scan reads each one's EEPROM (SII) and, for a SubDevice with a CoE mailbox, its
//! PDO assignment (0x1C1n) and mapping objects (0x16xx/0x1Axx) over SDO uploads, as ethercrab
//! itself configures the process data; then the SubDevices go back to INIT. The result is a
//! bus description ([`plc_rules::bus::scan::describe`]) whose layout is the one the bus comes
//! up with.
//!
//! Where a CoE SubDevice's EEPROM does not name a mapped entry, the scan reads the entry's
//! name and data type from the device's object dictionary through the SDO information service
//! (ETG.1000.6 §5.6.3, Get Entry Description; Get Object Description for an entry without a
//! name of its own): a drive's `x6040_00` becomes `controlword` (UINT), an EL3004's `x6000_11`
//! `value_1` (INT). A device that refuses the service, does not answer it in time, or answers
//! it in a way that breaks the protocol keeps the `xIIII_SS` names (a warning in the log says
//! why); see `coe_info` for the exchange.
//!
//! Everything read is device data and is checked: the EEPROM is read category by category up
//! to its end marker within the size it states (at most 128 KiB, [`MAX_CATEGORIES`]
//! categories), PDO counts are capped, and bad data is a [`ScanError`] naming the device.
//! Object descriptions are bounded the same way (timeouts, fragments, lengths), and bad ones
//! only cost the names.
//!
//! ```
//! use ethercat_sim::{Device, SimBus};
//! use plc_ethercat::{Options, Transport, scan::scan};
//!
//! let bus = SimBus::new(vec![Device::ek1100(), Device::el1004()]);
//! let transport = Transport::custom(move |tx, rx| {
//!     Ok(Box::new(ethercat_sim::inproc::spawn(tx, rx, bus)?))
//! });
//! let scanned = scan(transport, &Options::simulated())?;
//! assert_eq!(scanned.bus.devices[1].name, "el1004");
//! assert_eq!(scanned.bus.devices[1].entries[3].name, "input_4");
//! # Ok::<(), plc_ethercat::scan::ScanError>(())
//! ```

use super::error::EtherCatError;
use super::options::{Options, Transport};
use super::{MAX_PDI, MAX_SUBDEVICES};
use async_io::block_on;
use ethercrab::{MainDevice, SubDevice, SubDeviceRef};
use plc_rules::bus::scan::{CoeAssignment, ScannedDevice, describe, process_data_sms};
use plc_rules::bus::sii::{CATEGORIES_START, CategoryHeader, MAX_CATEGORIES, Sii};
use plc_rules::bus::{BusConfig, ConfigError, scan_file};
use std::fmt;
use std::time::Duration;

mod coe_info;

/// Most bytes read from one EEPROM: what 16-bit word addresses reach.
const MAX_EEPROM_BYTES: usize = 2 * 0x1_0000;

/// Most PDOs assigned to one SyncManager (ethercrab reads at most 64 from an EEPROM too).
const MAX_PDOS: u8 = 64;

/// Most mapped entries of one SubDevice: more than its share of [`MAX_PDI`] could hold in
/// 1-bit entries is not a real device.
const MAX_ENTRIES: usize = MAX_PDI * 8;

/// Byte offset of the EEPROM size word (word 0x3E: size in KiBit, minus 1).
const EEPROM_SIZE_WORD: usize = 0x7C;

/// What a scan found.
#[derive(Clone, Debug)]
pub struct ScannedBus {
    /// Each SubDevice in ring order, as read.
    pub devices: Vec<ScannedDevice>,
    /// The EEPROM bytes read from each SubDevice, from word 0 up to its end marker.
    pub eeproms: Vec<Vec<u8>>,
    /// The bus description made of them (validated).
    pub bus: BusConfig,
}

impl ScannedBus {
    /// The description as commented TOML, as `plc bus scan` prints it
    /// ([`scan_file::to_toml`]).
    pub fn to_toml(&self) -> String {
        scan_file::to_toml(&self.bus, &self.devices)
    }
}

/// Why a scan failed.
#[derive(Debug)]
pub enum ScanError {
    /// The transport did not open, or ethercrab could not bring the bus to PRE-OP.
    Bus(EtherCatError),
    /// A SubDevice's EEPROM or CoE objects could not be read or do not parse.
    Device {
        /// Its ring position.
        position: usize,
        /// Its name as ethercrab reports it.
        name: String,
        /// What went wrong.
        problem: String,
    },
    /// The devices found make no valid description (an entry no IEC type holds, a bus beyond
    /// plc-io's caps).
    Describe(ConfigError),
}

impl fmt::Display for ScanError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ScanError::Bus(e) => e.fmt(f),
            ScanError::Device {
                position,
                name,
                problem,
            } => write!(f, "SubDevice {position} ({name}): {problem}"),
            ScanError::Describe(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for ScanError {}

/// Scans the bus behind `transport`: see the module documentation. The SubDevices are left
/// in INIT.
pub fn scan(transport: Transport, options: &Options) -> Result<ScannedBus, ScanError> {
    let (maindevice, driver, _) =
        super::transport::open(transport, options).map_err(ScanError::Bus)?;
    let result = scan_group(&maindevice, options.timeouts.mailbox_response);
    // SAFETY: every ethercrab call in `scan_group` was awaited to its end, so no frame is in
    // flight, and the group it made was dropped there.
    let _ = unsafe { maindevice.release_all() };
    drop(driver);
    result
}

/// The scan itself; `mailbox_timeout` bounds each wait for an object description.
fn scan_group(
    md: &MainDevice<'static>,
    mailbox_timeout: Duration,
) -> Result<ScannedBus, ScanError> {
    let group =
        block_on(md.init_single_group::<MAX_SUBDEVICES, MAX_PDI>(ethercrab::std::ethercat_now))
            .map_err(|error| {
                ScanError::Bus(EtherCatError::Bus {
                    during: "scanning the bus (init to PRE-OP)",
                    error,
                })
            })?;
    // Every device is read before anything is returned, so the bus goes back to INIT after a
    // failure too.
    let read = (|| {
        let mut devices = Vec::new();
        let mut eeproms = Vec::new();
        for (position, sd) in group.iter(md).enumerate() {
            let fail = |problem: String| ScanError::Device {
                position,
                name: sd.name().to_owned(),
                problem,
            };
            let image = block_on(read_eeprom(md, &sd)).map_err(fail)?;
            let sii = Sii::parse(&image).map_err(|e| fail(e.to_string()))?;
            let device = if sii.has_coe() {
                let assigned = block_on(read_assignment(&sd, &sii)).map_err(fail)?;
                let mut device = ScannedDevice::from_coe(&sii, &assigned);
                // After ethercrab's SDO uploads of this device (see `coe_info` on the
                // mailbox counter).
                block_on(name_from_dictionary(
                    &sd,
                    &sii,
                    &mut device,
                    mailbox_timeout,
                ));
                device
            } else {
                ScannedDevice::from_sii(&sii)
            };
            devices.push(device);
            eeproms.push(image);
        }
        Ok((devices, eeproms))
    })();
    if let Err(e) = block_on(group.into_init(md)) {
        log::warn!(target: "plc_io::ethercat", "scan: the SubDevices did not go back to INIT: {e}");
    }
    let (devices, eeproms) = read?;
    let bus = describe(&devices).map_err(ScanError::Describe)?;
    Ok(ScannedBus {
        devices,
        eeproms,
        bus,
    })
}

/// Names and types the entries of `device` its EEPROM does not name from the device's object
/// dictionary (SDO information service, [`coe_info`]). Asked regardless of the EEPROM's "SDO
/// information" bit (General category, CoE details bit 1), which is not a reliable sign: the
/// AKD's EEPROM clears it, and the simulated AKD (like, as far as ethercrab's captures of a real
/// one suggest, the real drive) answers the service. A device without the service answers
/// with an error, or not at all within `timeout`, and is not asked again; either way its
/// entries keep the `xIIII_SS` names, with a note for the file's comment
/// ([`ScannedDevice::note`]) and a warning in the log.
async fn name_from_dictionary(
    sd: &SubDeviceRef<'_, &SubDevice>,
    sii: &Sii,
    device: &mut ScannedDevice,
    timeout: Duration,
) {
    if device
        .entries
        .iter()
        .all(|e| e.name.is_some() || e.index == 0)
    {
        return;
    }
    let why = match coe_info::EscMailbox::new(sd, sii, timeout).await {
        Ok(mut mailbox) => coe_info::name_entries(&mut mailbox, &mut device.entries).await,
        Err(why) => Some(why),
    };
    let unnamed = device
        .entries
        .iter()
        .filter(|e| e.name.is_none() && e.index != 0)
        .count();
    if unnamed > 0 {
        let why = why.unwrap_or_else(|| "the device answered an SDO information error".into());
        let note = format!(
            "{unnamed} entries have no name from its CoE object dictionary ({why}): they are \
             named by object index (x6000_11 is 0x6000:11); rename them from its data sheet"
        );
        log::warn!(target: "plc_io::ethercat", "scan: {}: {note}", sd.name());
        device.note = Some(note);
    }
}

/// Reads `buf.len()` bytes of the EEPROM from byte `at` (even).
async fn read_at(
    md: &MainDevice<'_>,
    sd: &SubDevice,
    at: usize,
    buf: &mut [u8],
) -> Result<(), String> {
    let word = u16::try_from(at / 2)
        .map_err(|_| format!("EEPROM byte {at:#x} is beyond 16-bit word addresses"))?;
    let n = sd
        .eeprom_read_raw(md, word, buf)
        .await
        .map_err(|e| format!("reading EEPROM word {word:#06x}: {e}"))?;
    if n != buf.len() {
        return Err(format!(
            "EEPROM word {word:#06x}: {n} of {} bytes read",
            buf.len()
        ));
    }
    Ok(())
}

/// The EEPROM from word 0 to the end marker: the header, then each category's header and
/// data in turn, within the size the EEPROM states (word 0x3E) and [`MAX_EEPROM_BYTES`].
async fn read_eeprom(md: &MainDevice<'_>, sd: &SubDevice) -> Result<Vec<u8>, String> {
    let mut image = vec![0u8; CATEGORIES_START];
    read_at(md, sd, 0, &mut image).await?;
    let stated = u16::from_le_bytes([image[EEPROM_SIZE_WORD], image[EEPROM_SIZE_WORD + 1]]);
    let limit = ((usize::from(stated) + 1) * 128).min(MAX_EEPROM_BYTES);
    for _ in 0..MAX_CATEGORIES {
        let at = image.len();
        if at + CategoryHeader::SIZE > limit {
            break;
        }
        let mut header = [0u8; CategoryHeader::SIZE];
        read_at(md, sd, at, &mut header).await?;
        image.extend_from_slice(&header);
        let h = CategoryHeader::from_bytes(header);
        if h.is_end() {
            break;
        }
        let start = at + CategoryHeader::SIZE;
        if start + h.len > limit {
            return Err(format!(
                "EEPROM category {} at word {:#06x} ({} bytes) runs past the {limit} bytes the \
                 EEPROM holds",
                h.kind,
                at / 2,
                h.len
            ));
        }
        let mut data = vec![0u8; h.len];
        read_at(md, sd, start, &mut data).await?;
        image.extend_from_slice(&data);
    }
    Ok(image)
}

/// The PDOs assigned to each process-data SyncManager n (object 0x1C10 + n) and their mapping
/// entries, read over CoE as ethercrab reads them to configure the process data.
async fn read_assignment(
    sd: &SubDeviceRef<'_, &SubDevice>,
    sii: &Sii,
) -> Result<Vec<CoeAssignment>, String> {
    let mut out = Vec::new();
    let mut total = 0usize;
    for (sm, _) in process_data_sms(sii) {
        let assign = 0x1C10 + u16::from(sm);
        let upload = |what: String| {
            move |e: ethercrab::error::Error| format!("reading {what} over CoE: {e}")
        };
        let count: u8 = sd
            .sdo_read(assign, 0)
            .await
            .map_err(upload(format!("{assign:#06x}:00")))?;
        if count > MAX_PDOS {
            return Err(format!(
                "{assign:#06x} assigns {count} PDOs to SyncManager {sm}, more than {MAX_PDOS}"
            ));
        }
        let mut pdos = Vec::new();
        for i in 1..=count {
            let pdo: u16 = sd
                .sdo_read(assign, i)
                .await
                .map_err(upload(format!("{assign:#06x}:{i:02x}")))?;
            let entries: u8 = sd
                .sdo_read(pdo, 0)
                .await
                .map_err(upload(format!("PDO {pdo:#06x}:00")))?;
            total += usize::from(entries);
            if total > MAX_ENTRIES {
                return Err(format!(
                    "its PDOs map more than {MAX_ENTRIES} entries, more than plc-io's process \
                     data holds"
                ));
            }
            let mut mapping = Vec::with_capacity(usize::from(entries));
            for j in 1..=entries {
                let m: u32 = sd
                    .sdo_read(pdo, j)
                    .await
                    .map_err(upload(format!("PDO {pdo:#06x}:{j:02x}")))?;
                mapping.push(m);
            }
            pdos.push((pdo, mapping));
        }
        out.push((sm, pdos));
    }
    Ok(out)
}
