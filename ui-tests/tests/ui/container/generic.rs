use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm<T> {
    value: T,
}

fn main() {}
