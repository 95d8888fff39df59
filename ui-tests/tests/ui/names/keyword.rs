use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(name = "END_VAR")]
    end: bool,
}

fn main() {}
