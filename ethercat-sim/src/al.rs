//! The application layer (AL) state machine: what AL status (0x0130) and AL status code
//! (0x0134) become when a MainDevice writes AL control (0x0120).
//!
//! The simulated terminals have no microcontroller: their ESC emulates the state machine, so
//! AL status simply follows AL control, the error-acknowledge bit 4 included (EMULATOR-NOTES
//! §5: after `BWR 0x0120 = 0x0011` the EK1100, EL2828 and EL2889 read back 0x0011). Only a
//! refusal injected with [`SimBus::refuse_transition`](crate::SimBus::refuse_transition)
//! makes one answer as a terminal with a microcontroller does when it rejects a request.

/// INIT.
pub const INIT: u8 = 1;
/// PRE-OP.
pub const PRE_OP: u8 = 2;
/// BOOT.
pub const BOOT: u8 = 3;
/// SAFE-OP.
pub const SAFE_OP: u8 = 4;
/// OP.
pub const OP: u8 = 8;

/// AL status bit 4: the requested state was refused (AL status code in 0x0134).
pub const ERROR: u16 = 0x0010;

/// AL status code 0x0011, "invalid requested state change".
pub const INVALID_STATE_CHANGE: u16 = 0x0011;
/// AL status code 0x0012, "unknown requested state".
pub const UNKNOWN_REQUESTED_STATE: u16 = 0x0012;
/// AL status code 0x001B, "sync manager watchdog": no process data for longer than the
/// SyncManager watchdog time; the device dropped to SAFE-OP.
pub const SYNC_MANAGER_WATCHDOG: u16 = 0x001B;
/// AL status code 0x001D, "invalid output configuration".
pub const INVALID_OUTPUT_CONFIGURATION: u16 = 0x001D;
/// AL status code 0x001E, "invalid input configuration".
pub const INVALID_INPUT_CONFIGURATION: u16 = 0x001E;

/// New AL status and AL status code after AL control was written with `control`.
///
/// `refused` is the code to answer with when the request is refused. A refusal keeps the
/// current state and sets the error bit, as an ESC with a microcontroller does. `latched`
/// is an error the device raised itself (an earlier refusal, a watchdog) that the MainDevice
/// has not acknowledged: until a request carries the acknowledge bit 4 the device keeps its
/// state, its error bit and its code (`code`).
pub(crate) fn on_control(
    status: u16,
    control: u16,
    refused: Option<u16>,
    latched: Option<u16>,
) -> (u16, u16) {
    match (refused, latched) {
        (_, Some(code)) if control & ERROR == 0 => (status | ERROR, code),
        (Some(code), _) => ((status & 0x000F) | ERROR, code),
        (None, _) => (control & 0x001F, 0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn status_follows_control_including_the_acknowledge_bit() {
        assert_eq!(on_control(0x0008, 0x0011, None, None), (0x0011, 0));
        assert_eq!(on_control(0x0011, 0x0002, None, None), (0x0002, 0));
    }

    #[test]
    fn a_refusal_keeps_the_state_and_sets_the_error_bit_and_code() {
        assert_eq!(
            on_control(0x0002, 0x0004, Some(INVALID_OUTPUT_CONFIGURATION), None),
            (0x0012, 0x001D)
        );
    }

    #[test]
    fn a_latched_error_ignores_requests_until_acknowledged() {
        let latched = Some(SYNC_MANAGER_WATCHDOG);
        assert_eq!(on_control(0x0014, 0x0008, None, latched), (0x0014, 0x001B));
        assert_eq!(on_control(0x0014, 0x0014, None, latched), (0x0014, 0));
        assert_eq!(on_control(0x0014, 0x0008, None, None), (0x0008, 0));
    }
}
