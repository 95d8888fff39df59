// The generated code does not depend on what `Result`, `Option`, `Ok`, `Some`, `None`,
// `Default` or `Value` mean where the struct is declared.
#![allow(dead_code, non_camel_case_types)]
use plc_core::GlobalMemory;

struct Result;
struct Option;
struct Ok;
struct Some;
struct None;
struct Default;
struct Value;
struct Err;
struct core;
struct __PlcVarsImage;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    #[plc(initial = 1, alarm(text = "Speed", low = -100, high = 100, severity = 700))]
    speed: i32,
    #[plc(alarm = "Stop", alarm_when = false)]
    run: bool,
    #[plc(at = "%IW0")]
    input: u16,
}

fn main() {
    let gm = <Gm as std::default::Default>::default();
    assert_eq!(gm.speed, 1);
}
