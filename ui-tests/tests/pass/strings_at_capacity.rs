use plc_core::{FixedString, GlobalMemory};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(initial = "12345678")]
    exact: FixedString<8>,
    #[plc(initial = "é€🦀")]
    utf8: FixedString<9>,
}

fn main() {
    let gm = Gm::default();
    assert_eq!(gm.exact, "12345678");
    assert_eq!(gm.utf8, "é€🦀");
}
