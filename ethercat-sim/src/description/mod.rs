//! The simulated bus from a bus description alone (feature `description`): each device the
//! description lists becomes the model with its identity, in the same ring order, so the
//! description is the one place that lists a machine's devices. The bus keeps the
//! description's names, so a plant model reads and sets its I/O by link name ([`links`]),
//! with values as [`value`] converts them.

mod links;
mod value;

pub use links::LinkError;
pub use value::LinkValue;

use crate::{Device, SimBus};
use plc_rules::bus::{BusConfig, BusLayout, ConfigError, DeviceConfig, Identity};
use std::fmt;
use std::path::Path;
use std::sync::Arc;

impl SimBus {
    /// The simulated bus of a bus description: for each device, in ring order, the model
    /// ([`Device::MODELS`]) whose vendor and product are the identity the description asks
    /// for (and whose revision is the one it gives, if it gives one). The bus keeps the
    /// description's names for [`set_input`](Self::set_input), [`input`](Self::input) and
    /// [`output`](Self::output).
    ///
    /// The description is checked first ([`BusConfig::validate`]); a device the simulator
    /// has no model for is refused, every one at once, naming it ([`DescriptionError`]).
    ///
    /// ```
    /// use ethercat_sim::SimBus;
    /// use plc_rules::bus::BusConfig;
    /// let config = BusConfig::from_toml_str(r#"
    ///     [[devices]]
    ///     name = "coupler"
    ///     identity = { vendor = 0x2, product = 0x044c2c52 }
    ///     [[devices]]
    ///     name = "lamps"
    ///     identity = { vendor = 0x2, product = 0x07d43052 }
    ///     entries = [{ name = "green", direction = "output", bits = 1, type = "BOOL" }]
    /// "#)?;
    /// let bus = SimBus::from_description(&config)?;
    /// assert_eq!(bus.device_names(), ["EK1100", "EL2004"]);
    /// assert_eq!(bus.output::<bool>("ethercat.lamps.green")?, false); // not in OP yet
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn from_description(config: &BusConfig) -> Result<SimBus, DescriptionError> {
        Self::build(config, "bus description")
    }

    /// [`from_description`](Self::from_description) of a description file: JSON if the name
    /// ends in `.json`, TOML otherwise ([`BusConfig::load`]). Errors name the file.
    pub fn from_description_file(path: impl AsRef<Path>) -> Result<SimBus, DescriptionError> {
        let path = path.as_ref();
        let config = BusConfig::load(path).map_err(DescriptionError::Refused)?;
        Self::build(&config, &path.display().to_string())
    }

    fn build(config: &BusConfig, origin: &str) -> Result<SimBus, DescriptionError> {
        config.validate().map_err(|mut e| {
            e.source = origin.to_owned();
            DescriptionError::Refused(e)
        })?;
        let models: Vec<Device> = Device::MODELS
            .iter()
            .filter_map(|n| Device::model(n))
            .collect();
        let mut devices = Vec::with_capacity(config.devices.len());
        let mut unmodelled = Vec::new();
        for (position, d) in config.devices.iter().enumerate() {
            match model_for(&models, position, d) {
                Ok(model) => devices.push(model),
                Err(refused) => unmodelled.push(refused),
            }
        }
        if !unmodelled.is_empty() {
            return Err(DescriptionError::NoModel {
                origin: origin.to_owned(),
                devices: unmodelled,
            });
        }
        let mut bus = SimBus::new(devices);
        bus.layout = Some(Arc::new(BusLayout::new(config)));
        Ok(bus)
    }
}

/// The model of the device at `position`, or why there is none.
fn model_for(models: &[Device], position: usize, d: &DeviceConfig) -> Result<Device, Unmodelled> {
    let wanted = d.identity;
    let same_product = models.iter().find(|m| {
        let (vendor, product, _) = m.identity();
        (vendor, product) == (wanted.vendor, wanted.product)
    });
    let refused = |model: Option<(String, u32)>| Unmodelled {
        position,
        name: d.name.clone(),
        identity: wanted,
        description: d.description.clone(),
        model,
    };
    match same_product {
        None => Err(refused(None)),
        Some(m) => {
            let revision = m.identity().2;
            match wanted.revision {
                Some(r) if r != revision => Err(refused(Some((m.name().to_owned(), revision)))),
                _ => Ok(m.clone()),
            }
        }
    }
}

/// Why [`SimBus::from_description`] refused a description.
#[derive(Debug)]
pub enum DescriptionError {
    /// The description itself: unreadable, not TOML or JSON, or failing its checks (the
    /// [`ConfigError`] lists every problem and names the file).
    Refused(ConfigError),
    /// Devices the simulator has no model for, every one.
    NoModel {
        /// Where the description came from: its file, or "bus description".
        origin: String,
        /// The devices, in ring order.
        devices: Vec<Unmodelled>,
    },
}

impl DescriptionError {
    /// The error with `origin` (a file name) as where the description came from, for a
    /// description read by the caller and handed over as a `BusConfig`.
    ///
    /// ```
    /// use ethercat_sim::SimBus;
    /// use plc_rules::bus::{BusConfig, devices};
    /// let mut drive = devices::akd("axis");
    /// drive.identity.product = 0x1234;
    /// let err = SimBus::from_description(&BusConfig { devices: vec![drive] }).unwrap_err();
    /// let err = err.with_origin("bus/machine.toml");
    /// assert!(err.to_string().starts_with("bus/machine.toml: no simulated bus: device `axis`"));
    /// ```
    pub fn with_origin(self, origin: impl Into<String>) -> Self {
        match self {
            DescriptionError::Refused(mut e) => {
                e.source = origin.into();
                DescriptionError::Refused(e)
            }
            DescriptionError::NoModel { devices, .. } => DescriptionError::NoModel {
                origin: origin.into(),
                devices,
            },
        }
    }
}

/// A device of a description that the simulator has no model for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unmodelled {
    /// Its ring position.
    pub position: usize,
    /// Its name in the description (the one links use).
    pub name: String,
    /// The identity the description asks for.
    pub identity: Identity,
    /// The description's free text for it (often the order number).
    pub description: String,
    /// The model with this vendor and product, with its revision, when only the revision
    /// differs.
    pub model: Option<(String, u32)>,
}

impl fmt::Display for Unmodelled {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let kind = match self.description.as_str() {
            "" => String::new(),
            text => format!(", \"{text}\""),
        };
        write!(
            f,
            "device `{}` (position {}{kind})",
            self.name, self.position
        )?;
        if let (Some((model, revision)), Some(wanted)) = (&self.model, self.identity.revision) {
            return write!(
                f,
                " asks for revision {wanted:#010x}, but the simulated {model} is revision \
                 {revision:#010x}: write `revision = {revision:#010x}` for it, or leave \
                 `revision` out to accept any"
            );
        }
        write!(
            f,
            " is {}, which the simulator has no model for",
            self.identity
        )
    }
}

/// The simulated devices with their vendor and product, for messages.
fn modelled() -> String {
    Device::MODELS
        .iter()
        .filter_map(|n| Device::model(n))
        .map(|m| {
            let (vendor, product, _) = m.identity();
            format!("{} (vendor {vendor:#x}, product {product:#010x})", m.name())
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl fmt::Display for DescriptionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DescriptionError::Refused(e) => write!(f, "no simulated bus: {e}"),
            DescriptionError::NoModel { origin, devices } => {
                write!(f, "{origin}: no simulated bus: ")?;
                match devices.as_slice() {
                    [one] => write!(f, "{one}")?,
                    all => {
                        write!(f, "{} devices cannot be simulated:", all.len())?;
                        for d in all {
                            write!(f, "\n  - {d}")?;
                        }
                    }
                }
                if devices.iter().any(|d| d.model.is_none()) {
                    write!(
                        f,
                        "\nThe simulator models {}: give a device the identity of one of them \
                         in the description, or run the description on hardware",
                        modelled()
                    )?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for DescriptionError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            DescriptionError::Refused(e) => Some(e),
            DescriptionError::NoModel { .. } => None,
        }
    }
}
