//! The tensile tester built as a module (`libtensile_tester.so`, built by `scripts/test.sh`)
//! runs exactly as the linked program: the same descriptor, bus description and initial
//! image, and cycle after cycle through a whole test the same image. That is what makes the
//! program's state its image: nothing it needs lives anywhere else.

use examples::tensile::drive::Drive;
use examples::tensile::{Gm, State, tick};
use plc_core::{GlobalMemory, Time, Value};
use plc_io::Context;
use plc_io::module::abi::CycleFacts;
use plc_io::module::{Module, trial::Trial};
use plc_io::shm::LayoutDescriptor;
use std::path::Path;
use std::time::Duration;
use zerocopy::IntoBytes;

const PERIOD_MS: u64 = 1;

fn module() -> Module {
    let bin = Path::new(env!("CARGO_BIN_EXE_tensile_tester"));
    let (lib, trial) = (
        bin.with_file_name("libtensile_tester.so"),
        bin.with_file_name("plc-module-trial"),
    );
    assert!(
        lib.is_file() && trial.is_file(),
        "{} or {} is missing: run the tests with scripts/test.sh (or `cargo build -p \
         tensile-tester-module -p plc-module` first)",
        lib.display(),
        trial.display()
    );
    Module::load(&lib, &Trial::with_program(trial)).unwrap()
}

/// What the operator and the sensors do, by cycle: a start, the specimen centred and lifted,
/// and at last its break. Bits go through `set`, which keeps a bit-mapped bool and its input
/// word together (the next unpack reads the word).
fn scenario(gm: &mut Gm, cycle: u64) {
    let mut set = |name: &str, on: bool| {
        let at = Gm::find(name).unwrap();
        gm.set_at(&at, Value::Bool(on)).unwrap();
    };
    match cycle {
        50 => set("cmd_start", true),
        51 => set("cmd_start", false),
        100 => {
            set("ls_centering_neg", true);
            set("ls_centering_pos", true);
            set("ls_lift_neg", true);
        }
        110 => set("ls_lift_neg", false),
        2500 => set("specimen_broken", true),
        _ => {}
    }
}

fn first_difference(a: &[u8], b: &[u8]) -> String {
    let at = a.iter().zip(b).position(|(x, y)| x != y).unwrap_or(0);
    let var = Gm::VARIABLES
        .iter()
        .find(|v| (v.offset..v.offset + v.size).contains(&at))
        .map_or("?", |v| v.name);
    format!("byte {at}, in `{var}`")
}

#[test]
fn the_module_describes_the_same_program() {
    let m = module();
    assert_eq!(m.name(), "tensile-tester-module");
    assert_eq!(m.descriptor(), &LayoutDescriptor::of::<Gm>());
    assert_eq!(m.layout_hash(), Gm::LAYOUT_HASH);
    let (file, text) = m
        .bus()
        .expect("the tensile tester names its bus description");
    assert_eq!(file, "bus/tensile_tester.toml");
    assert_eq!(text, include_str!("../bus/tensile_tester.toml"));
    assert_eq!(
        m.initial_image().unwrap(),
        Gm::default().to_image().as_bytes()
    );
}

#[test]
fn the_module_runs_a_whole_test_exactly_as_the_linked_program() {
    let m = module();
    let mut linked = Context::for_test(Gm::default());
    linked.stats.period = Duration::from_millis(PERIOD_MS);
    let mut image = m.initial_image().unwrap();
    let (mut drive_linked, mut drive_module) = (Drive::new(), Drive::new());
    let mut states = std::collections::BTreeSet::new();
    for cycle in 1..=3000u64 {
        let now = Time::from_millis((cycle * PERIOD_MS) as i64);
        // The linked program, as the runtime runs it.
        linked.cycle = cycle;
        linked.set_now(now);
        drive_linked.exchange(&mut linked.gm);
        scenario(&mut linked.gm, cycle);
        linked.gm.unpack_bits();
        tick(&mut linked);
        linked.gm.pack_bits();
        // The module, over its image, as a host runs it.
        let mut gm = Gm::from_image(zerocopy::FromBytes::ref_from_bytes(&image[..]).unwrap());
        drive_module.exchange(&mut gm);
        scenario(&mut gm, cycle);
        image = gm.to_image().as_bytes().to_vec();
        let facts = CycleFacts {
            cycle,
            now_ns: now.as_nanos() as u64,
            period_ns: PERIOD_MS * 1_000_000,
            inputs_valid: 1,
            ..CycleFacts::default()
        };
        m.unpack_bits(&mut image).unwrap();
        m.tick(&mut image, &facts).unwrap();
        m.pack_bits(&mut image).unwrap();

        let expected = linked.gm.to_image();
        assert!(
            expected.as_bytes() == image.as_slice(),
            "cycle {cycle}: the module's image differs at {}",
            first_difference(expected.as_bytes(), &image)
        );
        states.insert(linked.gm.machine_state);
    }
    // Not a comparison of two idle machines: the test ran and ended.
    for state in [
        State::Idle,
        State::Centering,
        State::Lifting,
        State::Testing,
    ] {
        assert!(
            states.contains(&(state as u8)),
            "never {state:?}: {states:?}"
        );
    }
    assert_eq!(
        linked.gm.tests_completed, 1,
        "the specimen broke and the test ended"
    );
}
