use plc_core::GlobalMemory;

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(link = "modbus.rack1.inputs")]
    a: u16,
    #[plc(link = "ethercat.el1004")]
    b: u16,
    #[plc(link = "ethercat.el-1004.inputs")]
    c: u16,
    #[plc(link = "ethercat.el1004.input 1")]
    d: bool,
}

fn main() {}
