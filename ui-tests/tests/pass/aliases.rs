// Every check that depends on the type works through type aliases too.
use plc_core::{FixedString, GlobalMemory};

type Word = u16;
type Flag = bool;
type Label = FixedString<12>;
type Row = [f32; 4];
type Force = f32;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    w: Word,
    #[plc(source = "w", bit = 15)]
    top: Flag,
    #[plc(initial = "ok")]
    label: Label,
    table: [Row; 2],
    #[plc(at = "%ID4", initial = 2)]
    force: Force,
    #[plc(iec_type = "WORD", initial = 65535)]
    mode: Word,
}

fn main() {
    let gm = Gm::default();
    assert_eq!((gm.label.as_str(), gm.force, gm.mode), ("ok", 2.0, 65535));
}
