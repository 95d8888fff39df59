//! Faults a test injects into one simulated SubDevice (see the `SimBus` methods
//! [`set_responding`](crate::SimBus::set_responding),
//! [`set_identity`](crate::SimBus::set_identity) and
//! [`refuse_transition`](crate::SimBus::refuse_transition)).

/// The faults of one device.
#[derive(Clone, Debug, Default)]
pub(crate) struct Faults {
    /// The device does not process datagrams and adds nothing to working counters (a
    /// terminal whose E-bus contacts lost power but still pass frames on).
    pub(crate) silent: bool,
    /// AL states the device refuses, with the AL status code it answers.
    pub(crate) refused: Vec<(u8, u16)>,
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
