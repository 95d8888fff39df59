use plc_core::GlobalMemory;

type Name = std::string::String;

#[derive(GlobalMemory)]
pub struct Gm {
    name: Name,
}

fn main() {}
