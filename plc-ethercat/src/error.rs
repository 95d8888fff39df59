//! Why the bus could not be started.

use super::config::ConfigError;
use super::layout::LayoutError;
use super::resolve::ResolveError;
use super::{MAX_PDI, MAX_SUBDEVICES};
use ethercrab::error::Error as CrabError;
use std::fmt;

/// Why the bus could not be started.
#[derive(Debug)]
pub enum EtherCatError {
    /// The bus description is not valid.
    Config(ConfigError),
    /// The struct's links do not fit the bus description.
    Links(ResolveError),
    /// The SubDevices found differ from the description (count or identity), by position.
    Identity(Vec<String>),
    /// The distributed clocks could not be set up: devices given `dc` in the description
    /// have no distributed clock, or the bus did not reach OP with SYNC0; one line each.
    DistributedClocks(Vec<String>),
    /// The runtime's period does not fit the description's SYNC0 period.
    Period(String),
    /// The process data ethercrab configured differs from the description.
    Layout(LayoutError),
    /// The transport could not be opened.
    Transport(String),
    /// ethercrab failed.
    Bus {
        /// What was being done.
        during: &'static str,
        /// ethercrab's error.
        error: CrabError,
    },
    /// `start` was called on a running backend, or `exchange` before `start`.
    State(&'static str),
    /// A start-up SDO was refused, or read back with another value.
    Startup {
        /// The device's name in the bus description.
        device: String,
        /// Its ring position.
        position: usize,
        /// The object and value.
        sdo: super::config::StartupSdo,
        /// What went wrong (ethercrab's abort code and text, or the value read back).
        problem: String,
    },
}

impl fmt::Display for EtherCatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EtherCatError::Config(e) => e.fmt(f),
            EtherCatError::Links(e) => e.fmt(f),
            EtherCatError::Identity(problems) => {
                f.write_str(
                    "the SubDevices on the bus do not match the bus description (fix the \
                     description or the wiring; nothing was switched to OP):",
                )?;
                for p in problems {
                    write!(f, "\n  - {p}")?;
                }
                Ok(())
            }
            EtherCatError::DistributedClocks(problems) => {
                f.write_str(
                    "the distributed clocks of the bus description could not be set up \
                     (nothing was switched to OP):",
                )?;
                for p in problems {
                    write!(f, "\n  - {p}")?;
                }
                Ok(())
            }
            EtherCatError::Period(problem) => f.write_str(problem),
            EtherCatError::Layout(e) => e.fmt(f),
            EtherCatError::Transport(e) => f.write_str(e),
            EtherCatError::Startup {
                device,
                position,
                sdo,
                problem,
            } => write!(
                f,
                "start-up SDO {sdo} = {} ({} bits) of device `{device}` (position {position}): \
                 {problem}; fix the object or the value in the bus description (nothing was \
                 switched to OP)",
                sdo.value, sdo.bits
            ),
            EtherCatError::Bus { during, error } => {
                write!(f, "EtherCAT error while {during}: {error}")?;
                match error {
                    CrabError::Timeout(_) => f.write_str(
                        " (no answer: check the cable, the interface name and that the \
                         SubDevices are powered)",
                    ),
                    CrabError::Capacity(_) | CrabError::PdiTooLong { .. } => write!(
                        f,
                        " (the bus is larger than plc-io's caps of {MAX_SUBDEVICES} SubDevices \
                         and {MAX_PDI} bytes of process data)"
                    ),
                    _ => Ok(()),
                }
            }
            EtherCatError::State(s) => f.write_str(s),
        }
    }
}

impl std::error::Error for EtherCatError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            EtherCatError::Config(e) => Some(e),
            EtherCatError::Links(e) => Some(e),
            EtherCatError::Layout(e) => Some(e),
            EtherCatError::Bus { error, .. } => Some(error),
            _ => None,
        }
    }
}

impl From<ConfigError> for EtherCatError {
    fn from(e: ConfigError) -> Self {
        EtherCatError::Config(e)
    }
}

impl From<ResolveError> for EtherCatError {
    fn from(e: ResolveError) -> Self {
        EtherCatError::Links(e)
    }
}

#[cfg(feature = "backend")]
/// Wraps ethercrab's error with what was being done.
pub(super) fn bus(during: &'static str) -> impl FnOnce(CrabError) -> EtherCatError {
    move |error| EtherCatError::Bus { during, error }
}
