use plc_core::GlobalMemory;

// Links compare case-insensitively: these are one output entry, written twice.
#[derive(GlobalMemory)]
#[plc(bus = "tests/bus/press.toml")]
pub struct Gm {
    #[plc(link = "ethercat.lamps.green", direction = "output")]
    ready: bool,
    #[plc(link = "ethercat.Lamps.Green", direction = "output")]
    also_ready: bool,
}

fn main() {}
