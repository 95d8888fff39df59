// `#[plc(crate = "...")]` for crates that re-export plc_core under another path.
mod reexport {
    pub use plc_core as plc;
}

#[derive(reexport::plc::GlobalMemory, Debug, Clone)]
#[plc(crate = "crate::reexport::plc")]
pub struct Gm {
    #[plc(initial = 7)]
    count: u8,
}

fn main() {
    use reexport::plc::GlobalMemory;
    assert_eq!(Gm::default().count, 7);
    assert_eq!(Gm::VARIABLES[0].name, "count");
}
