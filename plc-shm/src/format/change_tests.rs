//! The conversion of an online change: values carried by path, widened, narrowed back where
//! they fit, added, reset, removed, and refused by name.

use super::*;
use plc_core::{FixedString, GlobalMemory};
use zerocopy::IntoBytes;

fn planned<A: GlobalMemory, B: GlobalMemory>(
    resets: &[&str],
    direction: Direction,
) -> Result<ChangePlan, Vec<Refused>> {
    let resets: Vec<String> = resets.iter().map(|r| r.to_string()).collect();
    ChangePlan::new(
        &LayoutDescriptor::of::<A>(),
        &LayoutDescriptor::of::<B>(),
        &resets,
        direction,
    )
}

/// `to`'s program after the change from `from`, started from `to`'s `base`.
fn carried<A: GlobalMemory, B: GlobalMemory>(plan: &ChangePlan, from: &A, base: &B) -> B {
    let image = plan
        .apply(from.to_image().as_bytes(), base.to_image().as_bytes())
        .unwrap();
    let mut out = base.to_image();
    out.as_mut_bytes().copy_from_slice(&image);
    B::from_image(&out)
}

#[derive(GlobalMemory, Clone, Debug)]
struct Axis {
    target: f64,
    enable: bool,
}

#[derive(plc_core::PlcStruct, Clone, Debug)]
struct Station {
    door: bool,
    count: u16,
}

#[derive(plc_core::PlcStruct, Clone, Debug)]
struct StationV2 {
    #[plc(initial = 3)]
    mode: u8,
    count: u32,
    door: bool,
}

#[derive(GlobalMemory, Clone, Debug)]
struct V1 {
    count: i16,
    speed: f32,
    old_flag: bool,
    recipe: FixedString<8>,
    slots: [i16; 3],
    stations: [Station; 2],
}

#[derive(GlobalMemory, Clone, Debug)]
struct V2 {
    #[plc(initial = 7)]
    top_speed: u8,
    stations: [StationV2; 3],
    slots: [i16; 5],
    recipe: FixedString<20>,
    speed: f32,
    count: i32,
}

fn running() -> V1 {
    V1 {
        count: -300,
        speed: 2.5,
        old_flag: true,
        recipe: FixedString::from_str_truncate("PA6-GF30"),
        slots: [1, 2, 3],
        stations: [
            Station {
                door: true,
                count: 11,
            },
            Station {
                door: false,
                count: 12,
            },
        ],
    }
}

#[test]
fn every_value_that_still_exists_is_kept_by_path_wherever_it_moved() {
    let plan = planned::<V1, V2>(&[], Direction::Forward).unwrap();
    let after = carried(&plan, &running(), &V2::default());
    assert_eq!((after.count, after.speed), (-300, 2.5));
    assert_eq!(after.recipe.as_str(), "PA6-GF30");
    assert_eq!(
        after.slots,
        [1, 2, 3, 0, 0],
        "new elements at their initial value"
    );
    assert_eq!(
        (after.stations[0].door, after.stations[0].count),
        (true, 11)
    );
    assert_eq!(
        (after.stations[1].door, after.stations[1].count),
        (false, 12)
    );
    assert_eq!(after.stations[2].count, 0);
    assert_eq!(
        after.top_speed, 7,
        "an added variable starts at its initial value"
    );
    assert_eq!(after.stations[0].mode, 3, "so does an added member");
    assert_eq!(
        plan.widened,
        [
            "stations[0].count (UINT to UDINT)",
            "stations[1].count (UINT to UDINT)",
            "recipe (STRING(8) to STRING(20))",
            "count (INT to DINT)"
        ]
    );
    assert_eq!(plan.removed, ["old_flag"]);
    assert!(plan.added.contains(&"slots[4]".to_string()));
    assert!(plan.added.contains(&"stations[2].door".to_string()));
    assert!(!plan.changes_nothing());
}

#[test]
fn the_same_program_changes_nothing_and_every_byte_is_carried() {
    let plan = planned::<V1, V1>(&[], Direction::Forward).unwrap();
    assert!(plan.changes_nothing());
    let before = running();
    let after = carried(&plan, &before, &V1::default());
    assert_eq!(
        after.to_image().as_bytes(),
        before.to_image().as_bytes(),
        "every value carried"
    );
}

#[derive(GlobalMemory, Clone, Debug)]
struct Narrow {
    count: i16,
    speed: i16,
    old_flag: bool,
    recipe: FixedString<8>,
    slots: [i16; 3],
    stations: [Station; 2],
}

#[test]
fn a_type_iec_does_not_widen_to_is_refused_by_name_unless_reset() {
    let refused = planned::<V1, Narrow>(&[], Direction::Forward).unwrap_err();
    assert_eq!(refused.len(), 1, "{refused:?}");
    assert_eq!(refused[0].path, "speed");
    assert_eq!(
        refused[0].to_string(),
        "`speed`: is REAL in the running program and INT in the new one, which IEC 61131-3 \
         does not widen it to: reset it (`--reset speed`) to start from the new program's value"
    );
    let plan = planned::<V1, Narrow>(&["speed"], Direction::Forward).unwrap();
    assert_eq!(plan.reset, ["speed"]);
    let base = Narrow {
        speed: 42,
        ..Narrow::default()
    };
    let after = carried(&plan, &running(), &base);
    assert_eq!((after.speed, after.count), (42, -300));
}

#[test]
fn a_reset_names_a_structure_or_array_whole_and_a_reset_of_nothing_is_refused() {
    let plan = planned::<V1, V1>(&["stations", "slots[1]"], Direction::Forward).unwrap();
    assert_eq!(
        plan.reset,
        [
            "slots[1]",
            "stations[0].door",
            "stations[0].count",
            "stations[1].door",
            "stations[1].count"
        ]
    );
    let refused = planned::<V1, V1>(&["station", "nothing"], Direction::Forward).unwrap_err();
    let paths: Vec<&str> = refused.iter().map(|r| r.path.as_str()).collect();
    assert_eq!(
        paths,
        ["station", "nothing"],
        "a prefix of a name is no path"
    );
    assert!(refused[0].why.contains("names no value"));
}

#[test]
fn going_back_narrows_a_value_that_fits_and_refuses_one_that_does_not() {
    // Forward V1 -> V2 widened `count` and the recipe; back V2 -> V1 narrows them.
    assert!(planned::<V2, V1>(&[], Direction::Forward).is_err());
    let back = planned::<V2, V1>(&[], Direction::Back).unwrap();
    assert!(back.narrowed.contains(&"count (DINT to INT)".to_string()));
    let mut now = V2 {
        count: -300,
        ..V2::default()
    };
    now.recipe = FixedString::from_str_truncate("short");
    // The previous program's image at the change: a removed variable comes back with it.
    let at_change = running();
    let after = carried(&back, &now, &at_change);
    assert_eq!((after.count, after.recipe.as_str()), (-300, "short"));
    assert!(after.old_flag, "back with its value at the change");
    now.count = 100_000;
    now.recipe = FixedString::from_str_truncate("a recipe too long");
    let refused = back
        .apply(now.to_image().as_bytes(), at_change.to_image().as_bytes())
        .unwrap_err();
    let paths: Vec<&str> = refused.iter().map(|r| r.path.as_str()).collect();
    assert_eq!(paths, ["count", "recipe"], "in the declaration's order");
    assert!(
        refused[0]
            .why
            .starts_with("holds 100000, which does not fit its INT"),
        "{}",
        refused[0].why
    );
}

#[test]
fn images_of_other_sizes_are_refused_and_nothing_is_made() {
    let plan = planned::<Axis, Axis>(&[], Direction::Forward).unwrap();
    let image = Axis::default().to_image();
    let refused = plan
        .apply(&image.as_bytes()[1..], image.as_bytes())
        .unwrap_err();
    assert!(refused[0].why.contains("where its descriptor says"));
}
