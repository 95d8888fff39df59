//! The EtherCAT SubDevice Controller (ESC): register addresses the simulator gives meaning to,
//! the facts that tell one ESC from another ([`EscInfo`]), and which registers exist and
//! which can be written, since both decide working counters.

/// Register addresses (ETG.1000.4 / Beckhoff ESC datasheet section II).
pub mod reg {
    /// Type, revision, build, FMMU and SM counts, RAM size, port descriptor, features.
    pub const INFO: usize = 0x0000;
    /// ESC features supported (u16).
    pub const FEATURES: usize = 0x0008;
    /// Configured station address (u16).
    pub const STATION_ADDRESS: usize = 0x0010;
    /// Configured station alias (u16), loaded from SII word 4.
    pub const STATION_ALIAS: usize = 0x0012;
    /// DL control byte 3, bit 0: station alias enabled for FPxx addressing.
    pub const DL_CONTROL_ALIAS: usize = 0x0103;
    /// DL status (u16).
    pub const DL_STATUS: usize = 0x0110;
    /// AL control (u16).
    pub const AL_CONTROL: usize = 0x0120;
    /// AL status (u16).
    pub const AL_STATUS: usize = 0x0130;
    /// AL status code (u16).
    pub const AL_STATUS_CODE: usize = 0x0134;
    /// RX error counters, two bytes per port (invalid frames, then RX errors). A write to any
    /// of them clears all eight bytes; the value written does not matter.
    pub const RX_ERROR_COUNTERS: std::ops::Range<usize> = 0x0300..0x0308;
    /// SII EEPROM configuration / PDI access.
    pub const SII_CONFIG: usize = 0x0500;
    /// SII EEPROM control/status (u16).
    pub const SII_CONTROL: usize = 0x0502;
    /// SII EEPROM word address (u32).
    pub const SII_ADDRESS: usize = 0x0504;
    /// SII EEPROM data (8 bytes).
    pub const SII_DATA: usize = 0x0508;
    /// First FMMU (16 bytes each).
    pub const FMMU0: usize = 0x0600;
    /// First SyncManager (8 bytes each).
    pub const SM0: usize = 0x0800;
    /// DC receive time port 0 (u32; a write latches all ports).
    pub const DC_RECEIVE_TIME: usize = 0x0900;
    /// DC system time (u64).
    pub const DC_SYSTEM_TIME: usize = 0x0910;
    /// DC receive time of the processing unit (u64).
    pub const DC_RECEIVE_TIME_PU: usize = 0x0918;
    /// DC system time offset (u64).
    pub const DC_SYSTEM_TIME_OFFSET: usize = 0x0920;
    /// DC system time delay (u32).
    pub const DC_SYSTEM_TIME_DELAY: usize = 0x0928;
    /// DC system time difference (u32, read-only): sign (bit 31, local copy smaller) and
    /// magnitude of the mean difference between the local copy and the received system time.
    pub const DC_SYSTEM_TIME_DIFFERENCE: usize = 0x092C;
    /// DC speed counter start (u16): bandwidth of the time control loop; a write resets it.
    pub const DC_SPEED_COUNTER_START: usize = 0x0930;
    /// DC speed counter diff (u16, two's complement, read-only): the loop's rate correction.
    pub const DC_SPEED_COUNTER_DIFF: usize = 0x0932;
    /// DC system time difference filter depth (u8, bits 0-3).
    pub const DC_TIME_FILTER_DEPTH: usize = 0x0934;
    /// DC speed counter filter depth (u8, bits 0-3).
    pub const DC_SPEED_FILTER_DEPTH: usize = 0x0935;
    /// DC cyclic unit control (u8): bit 0 assigns the SYNC out unit to the PDI.
    pub const DC_CYCLIC_UNIT_CONTROL: usize = 0x0980;
    /// DC activation (u8): bit 0 SYNC out unit, bit 1 SYNC0, bit 2 SYNC1 (see `dc/sync0.rs`).
    pub const DC_ACTIVATION: usize = 0x0981;
    /// DC pulse length of the SYNC signals (u16, read-only, from SII word 2; 0 is
    /// acknowledge mode).
    pub const DC_PULSE_LENGTH: usize = 0x0982;
    /// DC activation status (u8, read-only): bit 0 first SYNC0 pulse pending.
    pub const DC_ACTIVATION_STATUS: usize = 0x0984;
    /// DC SYNC0 status (u8, read-only): bit 0 set by a SYNC0 pulse.
    pub const DC_SYNC0_STATUS: usize = 0x098E;
    /// DC start time of cyclic operation (u64): written, the first SYNC0 pulse; read, the
    /// next one.
    pub const DC_SYNC0_START_TIME: usize = 0x0990;
    /// DC SYNC0 cycle time (u32, ns; 0 is a single pulse).
    pub const DC_SYNC0_CYCLE_TIME: usize = 0x09A0;
    /// DC SYNC1 cycle time (u32, ns; kept, SYNC1 is not generated).
    pub const DC_SYNC1_CYCLE_TIME: usize = 0x09A4;
    /// Process data RAM starts here.
    pub const PROCESS_RAM: usize = 0x1000;
}

/// Bytes of ESC address space modelled: registers 0x0000-0x0FFF and 4 KiB of process RAM.
pub const SPACE: usize = 0x2000;

/// What distinguishes one ESC from another, as far as a MainDevice can see.
///
/// The values of the device models come from the captures (EMULATOR-NOTES §6); where a register
/// was never captured the model says so.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EscInfo {
    /// Register 0x0000, ESC type (0x11 ET1100, 0x12 ET1200 family as Beckhoff numbers them).
    pub esc_type: u8,
    /// Register 0x0001, revision.
    pub revision: u8,
    /// Register 0x0002, build.
    pub build: u16,
    /// Register 0x0004: FMMUs the ESC has (registers of the others do not exist).
    pub fmmus: u8,
    /// Register 0x0005: SyncManagers the ESC has.
    pub sync_managers: u8,
    /// Register 0x0006: process RAM in KiB.
    pub ram_kib: u8,
    /// Register 0x0007: port descriptor.
    pub ports: u8,
    /// Register 0x0008: features (bit 2 DC, bit 3 64-bit DC, bit 8 enhanced DC sync).
    pub features: u16,
    /// Whether the DC system-time unit (0x0910-0x09FF) exists. The EL2828 announces DC but
    /// does not count these registers (WKC 0 in capture \[A\]), so this is separate from
    /// `features`.
    pub dc_system_time: bool,
    /// Bits 0-3 of DL status 0x0110 (bit 0 PDI operational, bit 1 PDI watchdog): 0x1 on the
    /// EK1100, 0x3 on the terminals.
    pub dl_status_pdi: u8,
    /// SII control/status 0x0502 when idle: 0x0040 (8-byte reads) or 0x0050.
    pub sii_idle: u16,
}

impl EscInfo {
    /// Whether DC receive-time registers (0x0900-0x090F) exist.
    pub fn has_dc(&self) -> bool {
        self.features & 0x0004 != 0
    }

    /// Whether a datagram touching `[ado, ado + len)` finds registers here. FMMUs and
    /// SyncManagers beyond the ESC's count, and DC registers of an ESC without them, do not
    /// exist, and a datagram that finds none adds nothing to the working counter
    /// (EMULATOR-NOTES §2: reset BWRs of FMMU3-7 give WKC 1 on a bus with one ET1100).
    pub fn has(&self, ado: usize, len: usize) -> bool {
        let end = ado + len.max(1);
        let within = |from: usize, to: usize| ado >= from && end <= to;
        let missing_fmmus = within(reg::FMMU0 + 16 * self.fmmus as usize, 0x0700);
        let missing_sms = within(reg::SM0 + 8 * self.sync_managers as usize, 0x0880);
        let missing_dc = match (self.has_dc(), self.dc_system_time) {
            (false, _) => within(reg::DC_RECEIVE_TIME, 0x0A00),
            (true, false) => within(reg::DC_SYSTEM_TIME, 0x0A00),
            (true, true) => false,
        };
        !(missing_fmmus || missing_sms || missing_dc)
    }
}

/// Whether a master write changes the byte at `a`: a write that finds only read-only
/// registers adds nothing to the working counter (BWR 0x092C gives WKC 0 in capture \[A\]).
pub fn writable(a: usize) -> bool {
    !matches!(
        a,
        0x0000..=0x000F
            | 0x0110..=0x0111
            | 0x0130..=0x013F
            | 0x0904..=0x090F
            | 0x0918..=0x091F
            | 0x092C..=0x092F
            | 0x0932..=0x0933
            | 0x0982..=0x098F
            | 0x0998..=0x099F
    )
}

/// Whether any byte of `[ado, ado + len)` is writable.
pub fn any_writable(ado: usize, len: usize) -> bool {
    (ado..ado + len.max(1)).any(writable)
}
