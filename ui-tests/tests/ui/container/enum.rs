use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub enum Gm {
    Idle,
    Running,
}

fn main() {}
