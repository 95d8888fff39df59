use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
#[plc(bus = "tests/bus/nowhere.toml")]
pub struct Gm {
    #[plc(link = "ethercat.io.input1")]
    button: bool,
}

fn main() {}
