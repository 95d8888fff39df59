use plc_core::{GlobalMemory, Time};

#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(initial = "T#1h75m")]
    later_part_too_large: Time,
    #[plc(initial = "T#5s1m")]
    units_out_of_order: Time,
    #[plc(initial = "5s")]
    no_prefix: Time,
    #[plc(initial = "T#1.5m30s")]
    fraction_not_last: plc_core::Time,
    #[plc(initial = "T#106752d")]
    beyond_ltime: Time,
    #[plc(initial = 5000)]
    bare_number: Time,
    #[plc(initial = true)]
    a_bool: [Time; 2],
}

fn main() {}
