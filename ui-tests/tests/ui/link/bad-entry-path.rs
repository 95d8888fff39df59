use plc_core::GlobalMemory;

// A link's entry may be a dotted path (`ethercat.motion.x.position`), each part an identifier.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(link = "ethercat.motion.x..position")]
    x_position: i32,
    #[plc(link = "ethercat.motion.x.1st")]
    x_first: i32,
}

fn main() {}
