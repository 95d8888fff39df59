use plc_core::{FixedString, GlobalMemory, PlcStruct};

type Label = FixedString<8>;
type Flag = bool;
type Force = f64;

#[derive(PlcStruct, Debug, Clone)]
pub struct Station {
    door: bool,
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(alarm = "Station fault")]
    station: Station,
    #[plc(alarm = "Bad label")]
    label: Label,
    #[plc(alarm(text = "Flag", high = 1))]
    flag: Flag,
    // Fine: an alias of bool, and of a number with limits.
    #[plc(alarm = "Flag set")]
    ok_flag: Flag,
    #[plc(alarm(text = "Force", high = 10.0))]
    force: Force,
}

fn main() {}

type Mode = u8;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Suppressed {
    #[plc(alarm(text = "Door", suppress_when = "mode"))]
    door: bool,
    mode: Mode,
    #[plc(alarm(text = "Fan", suppress_when = "off"))]
    fan: bool,
    off: Flag,
}
