use plc_core::{FixedString, GlobalMemory, IecType, Time, Value};

type Delay = Time;

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Gm {
    #[plc(initial = "T#1s500ms", nonvolatile)]
    start_delay: Time,
    #[plc(initial = "LTIME#-2h_30m")]
    offset: plc_core::Time,
    #[plc(initial = "lt#1.5s")]
    steps: [Time; 3],
    #[plc(initial = "T#250ms")]
    aliased: Delay,
    #[plc(initial = "T#5s")]
    label: FixedString<8>,
    plain: Time,
}

fn main() {
    let gm = Gm::default();
    assert_eq!(gm.start_delay, Time::from_millis(1500));
    assert_eq!(gm.offset, Time::from_secs(-9000));
    assert_eq!(gm.steps, [Time::from_millis(1500); 3]);
    assert_eq!(gm.aliased, Time::from_millis(250));
    assert_eq!(gm.label, "T#5s", "text that looks like a duration stays text");
    assert_eq!(gm.plain, Time::ZERO);
    let v = &Gm::VARIABLES[0];
    assert_eq!((v.iec_type, v.size, v.initial), (IecType::Ltime, 8, Some("\"T#1s500ms\"")));
    assert_eq!(Gm::VARIABLES[2].size, 24);
    let mut gm = gm;
    let steps = Gm::index_of("steps").unwrap();
    gm.set(steps, 2, Value::Time(Time::from_millis(20))).unwrap();
    assert_eq!(gm.get(steps, 2), Value::Time(Time::from_millis(20)));
    assert!(gm.set(steps, 0, Value::Int(20)).is_err(), "a bare number is no duration");
    let image = gm.to_image();
    assert_eq!(Gm::from_image(&image), gm);
}
