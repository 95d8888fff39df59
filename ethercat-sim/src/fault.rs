//! Faults a test injects into one simulated SubDevice (see the `SimBus` methods
//! [`set_responding`](crate::SimBus::set_responding),
//! [`power_cycle`](crate::SimBus::power_cycle),
//! [`trip_watchdog`](crate::SimBus::trip_watchdog),
//! [`set_identity`](crate::SimBus::set_identity) and
//! [`refuse_transition`](crate::SimBus::refuse_transition)).

/// The faults of one device.
#[derive(Clone, Debug, Default)]
pub(crate) struct Faults {
    /// The link into the device's port 0 is down (it lost power, or its cable was pulled):
    /// frames turn back at the device before it, so neither this device nor any behind it
    /// sees them.
    pub(crate) link_lost: bool,
    /// AL states the device refuses, with the AL status code it answers.
    pub(crate) refused: Vec<(u8, u16)>,
    /// The device itself set the AL error bit (a refused request, a tripped watchdog): it
    /// ignores state requests until the MainDevice acknowledges (AL control bit 4),
    /// (ETG.1000.6). Holds the AL status code.
    pub(crate) latched: Option<u16>,
}

impl Faults {
    /// The code to answer a request for `state` with, if the device refuses it.
    pub(crate) fn refusal(&self, state: u8) -> Option<u16> {
        self.refused
            .iter()
            .find(|(s, _)| *s == state)
            .map(|&(_, code)| code)
    }

    /// Refuses `state` with `code` from now on (a later call for the same state replaces it).
    pub(crate) fn refuse(&mut self, state: u8, code: u16) {
        self.refused.retain(|(s, _)| *s != state);
        self.refused.push((state, code));
    }

    /// Accepts `state` again.
    pub(crate) fn accept(&mut self, state: u8) {
        self.refused.retain(|(s, _)| *s != state);
    }
}

/// How a simulated SubDevice's CoE server misanswers the SDO information service, for tests
/// of a MainDevice that reads object names ([`Device::set_sdo_info_fault`](crate::Device::set_sdo_info_fault)).
/// SDO uploads and downloads are answered as before.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SdoInfoFault {
    /// Every SDO information request is answered with an SDO Info Error (opcode 0x07, abort
    /// code 0x05040001, "command specifier not valid or unknown"), as by a device without the
    /// service.
    Refused,
    /// The reply's mailbox header states more bytes than the input mailbox holds.
    Oversized,
    /// The reply is a fragment that says more follow, and every time the MainDevice empties
    /// the input mailbox another one arrives, without end.
    EndlessFragments,
}
