//! The quick benchmark runner: `cargo run --release -p plc-bench --bin plc-bench -- --quick`.
//! Prints one `name: value` line per figure, ratios measured side by side in the same run
//! (machines here are shared and noisy), then `plc-bench: ok`. Method in BENCHMARKS.md.
//!
//! `--only cycle,structures,cycle_10k,snapshot,process_image,derive,import,bus,tools,opcua,commissioning,flood,drives,alarms,sparkplug`
//! runs some groups of figures.
//! `cycle_10k`, `derive`, `tools`, `opcua` and `sparkplug` compile generated crates: their first run takes
//! minutes.
//! `--full` adds the opt-in group `cycle_100k` (a 100,000-variable crate: its build takes far
//! longer than CI can spend) unless `--only` names the groups (`--only cycle_100k` names it),
//! and makes the `alarms` group's flood the issue's minute instead of 5 s.

use plc_bench::cycle::{FrameworkCycle, HandCycle, MemcpyFloor, runtime_vs_memcpy};
use plc_bench::derive_check::{Crate, Flavour};
use plc_bench::gm1k::{Gm1k, Hand1k, IMAGE_SIZE};
use plc_bench::located;
use plc_bench::timing::{median_per_iter, ratio, side_by_side};
use plc_core::{GlobalMemory, IecAddress};
use plc_io::shm::SharedGlobalMemory;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// A 64 KiB image: every word equals `seq` in a consistent snapshot.
#[derive(GlobalMemory, Clone, Debug)]
pub struct Big64k {
    seq: u64,
    data: [u64; 8191],
}

/// The groups of figures, in the order they run.
const GROUPS: [&str; 16] = [
    "cycle",
    "structures",
    "cycle_10k",
    "snapshot",
    "process_image",
    "derive",
    "import",
    "bus",
    "tools",
    "opcua",
    "commissioning",
    "flood",
    "drives",
    "alarms",
    "sparkplug",
    "online_change",
];

/// Groups that run only when asked for (`--full`, or by name in `--only`).
const OPT_IN: [&str; 1] = ["cycle_100k"];

fn main() {
    // The online change group tries its modules in a child: this program, run again.
    plc_io::module::trial::serve_if_asked();
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("--publisher") {
        publisher(&args[2]);
        return;
    }
    let quick = args.iter().any(|a| a == "--quick");
    let full = args.iter().any(|a| a == "--full");
    let named = args.iter().position(|a| a == "--only");
    let mut only: Vec<&str> = match named {
        Some(i) => args
            .get(i + 1)
            .map(|s| s.split(',').collect())
            .unwrap_or_default(),
        None => GROUPS.to_vec(),
    };
    // With `--only` the groups are the ones named: `--full --only alarms` is the minute's
    // flood, not also the 100k crate's build.
    if full && named.is_none() {
        for group in OPT_IN {
            if !only.contains(&group) {
                only.push(group);
            }
        }
    }
    if let Some(bad) = only
        .iter()
        .find(|g| !GROUPS.contains(g) && !OPT_IN.contains(g))
    {
        eprintln!(
            "plc-bench: no group `{bad}`; the groups are {}, and with --full {}",
            GROUPS.join(", "),
            OPT_IN.join(", ")
        );
        std::process::exit(2);
    }
    let batches = if quick { 15 } else { 61 };
    // A cycle takes well under a microsecond: many batches cost little and steady the ratio.
    let cycle_batches = batches * 4;
    let segment = format!("plc_bench_{}", std::process::id());
    for group in only {
        match group {
            "cycle" => cycle(&segment, cycle_batches),
            "structures" => structures(&segment, cycle_batches),
            "cycle_10k" => match plc_bench::cycle_10k::run(batches) {
                Ok(lines) => {
                    print!("{lines}");
                    memcpy_growth(batches, 1);
                }
                Err(e) => fail(&e),
            },
            "cycle_100k" => match plc_bench::cycle_10k::run_100k(batches) {
                Ok(lines) => {
                    print!("{lines}");
                    memcpy_growth(batches, 10);
                }
                Err(e) => fail(&e),
            },
            "snapshot" => snapshot_latency(&segment, if quick { 3 } else { 10 }),
            "process_image" => process_image(batches),
            "derive" => derive_check(if quick { 1 } else { 3 }),
            "bus" => match plc_bench::bus::run(quick) {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&format!("bus: {e}")),
            },
            "tools" => match plc_bench::tools::run(quick) {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&e),
            },
            "opcua" => match plc_bench::opcua::run(quick) {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&e),
            },
            "commissioning" => match plc_bench::commissioning::run(quick, cycle_batches) {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&format!("commissioning: {e}")),
            },
            "alarms" => match plc_bench::alarms::run(plc_bench::alarms::Scale::of(
                quick,
                full,
                cycle_batches,
            )) {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&format!("alarms: {e}")),
            },
            "sparkplug" => match plc_bench::sparkplug::run(quick) {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&format!("sparkplug: {e}")),
            },
            "flood" => match plc_bench::commissioning::flood() {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&format!("flood: {e}")),
            },
            "online_change" => match plc_bench::online_change::run() {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&format!("online_change: {e}")),
            },
            "drives" => match plc_bench::drives::run(quick) {
                Ok(lines) => print!("{lines}"),
                Err(e) => fail(&format!("drives: {e}")),
            },
            _ => import_10k(),
        }
    }
    println!("plc-bench: ok");
}

/// Ends the run: a figure could not be measured.
fn fail(why: &str) -> ! {
    eprintln!("plc-bench: {why}");
    std::process::exit(1);
}

/// The cycle on Gm1k: framework against the same work hand-written, and against memcpy.
fn cycle(segment: &str, batches: usize) {
    let mut framework = FrameworkCycle::<Gm1k>::new(segment).expect("segment");
    let mut hand = HandCycle::<Hand1k>::default();
    let mut floor = MemcpyFloor::new(IMAGE_SIZE);
    let (ours, theirs) = side_by_side(batches, 2000, || framework.step(), || hand.step());
    let memcpy = median_per_iter(batches, 2000, || floor.step());
    let outputs = median_per_iter(batches, 2000, || framework.runtime_step());
    let (runtime, runtime_memcpy) =
        runtime_vs_memcpy::<Gm1k>(&format!("{segment}_rt"), batches, 2000).expect("runtime");
    println!("cycle_1k_ns: {}", ours.as_nanos());
    println!("cycle_1k_handwritten_ns: {}", theirs.as_nanos());
    println!("cycle_1k_memcpy_ns: {}", memcpy.as_nanos());
    println!("cycle_1k_vs_handwritten: {:.2}", ratio(ours, theirs));
    println!("cycle_1k_vs_memcpy: {:.2}", ratio(ours, memcpy));
    println!("cycle_1k_outputs_vs_memcpy: {:.2}", ratio(outputs, memcpy));
    println!("cycle_1k_runtime_ns: {}", runtime.as_nanos());
    println!(
        "cycle_1k_runtime_vs_memcpy: {:.2}",
        ratio(runtime, runtime_memcpy)
    );
    // Where the time goes: each part alone, ours and hand-written side by side.
    let hand_parts = HandCycle::<Hand1k>::parts();
    for ((name, part), (_, hand_part)) in
        FrameworkCycle::<Gm1k>::parts().into_iter().zip(hand_parts)
    {
        let (ours, theirs) = side_by_side(
            batches / 4,
            2000,
            || part(&mut framework),
            || hand_part(&mut hand),
        );
        println!("cycle_1k_{name}_ns: {}", ours.as_nanos());
        println!("cycle_1k_{name}_handwritten_ns: {}", theirs.as_nanos());
    }
}

/// How the memcpy floor itself grows from `small_k` thousand variables to ten times as many
/// (images of 4,488 bytes per 1,000 variables): the part of the cycle's growth that is the
/// memory hierarchy's. Two figures: the two copies of `cycle_1k_vs_memcpy`
/// (`memcpy_<large>_over_<small>`), and the cycle's four copies through its three buffers
/// (`memcpy_cycle_buffers_<large>_over_<small>`). From 1k to 10k the cycle's buffers leave the
/// L1 data cache for L2; from 10k to 100k they fill most of this machine's 2 MiB L2.
fn memcpy_growth(batches: usize, small_k: usize) {
    type Floor = fn(usize) -> MemcpyFloor;
    let len = IMAGE_SIZE * small_k;
    let floors: [(&str, Floor); 2] = [
        ("memcpy", MemcpyFloor::new),
        ("memcpy_cycle_buffers", MemcpyFloor::cycle_copies),
    ];
    // As many bytes per batch as the 1k cycle's 200 steps of ten.
    let iters = (200 / small_k).max(2) as u32;
    for (figure, floor) in floors {
        let (mut one, mut ten) = (floor(len), floor(10 * len));
        let (small_t, large_t) = side_by_side(
            batches,
            iters,
            || {
                for _ in 0..10 {
                    one.step();
                }
            },
            || ten.step(),
        );
        println!(
            "{figure}_{}k_over_{small_k}k: {:.2}",
            10 * small_k,
            10.0 * ratio(large_t, small_t)
        );
    }
}

/// The cycle on 100 ten-member structures against the same 1,000 variables flat: what the
/// structure level costs per cycle.
fn structures(segment: &str, batches: usize) {
    use plc_bench::axes::{GmAxes, GmAxesFlat};
    let mut nested = FrameworkCycle::<GmAxes>::new(&format!("{segment}_axes")).expect("segment");
    let mut flat = FrameworkCycle::<GmAxesFlat>::new(&format!("{segment}_flat")).expect("segment");
    let (ours, theirs) = side_by_side(batches, 2000, || nested.step(), || flat.step());
    println!("cycle_struct_ns: {}", ours.as_nanos());
    println!("cycle_struct_flat_ns: {}", theirs.as_nanos());
    println!("cycle_struct_vs_flat: {:.2}", ratio(ours, theirs));
}

/// The other process: publishes a 64 KiB image at 1 kHz.
fn publisher(segment: &str) {
    let owner = SharedGlobalMemory::<Big64k>::create(segment).expect("segment");
    let mut gm = Big64k::default();
    let mut next = Instant::now();
    while owner.owner_state() != plc_io::shm::OwnerState::Gone {
        gm.seq += 1;
        gm.data = [gm.seq; 8191];
        owner.publish(&gm).expect("publish");
        next += Duration::from_millis(1);
        std::thread::sleep(next.saturating_duration_since(Instant::now()));
        if gm.seq > 600_000 {
            break;
        }
    }
}

/// A reader snapshots as fast as it can while another process publishes at 1 kHz.
fn snapshot_latency(segment: &str, seconds: u64) {
    let name = format!("{segment}_64k");
    let mut child = std::process::Command::new(std::env::current_exe().expect("exe"))
        .args(["--publisher", &name])
        .spawn()
        .expect("spawn publisher");
    let reader = loop {
        if let Ok(r) = SharedGlobalMemory::<Big64k>::attach(&name) {
            break r;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let mut image = Big64k::default().to_image();
    let mut lat = Vec::new();
    let mut torn = 0u64;
    let end = Instant::now() + Duration::from_secs(seconds);
    while Instant::now() < end {
        let t = Instant::now();
        reader.snapshot_image_into(&mut image).expect("snapshot");
        lat.push(t.elapsed());
        let g = Big64k::from_image(&image);
        if g.data.iter().any(|&w| w != g.seq) {
            torn += 1;
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    drop(reader);
    // Taking the killed publisher's segment over and dropping it removes its socket and lock file.
    drop(SharedGlobalMemory::<Big64k>::create(&name));
    lat.sort();
    let p99 = lat[lat.len() * 99 / 100];
    println!("snapshot_p99_us_64k: {:.1}", p99.as_secs_f64() * 1e6);
    println!("snapshot_count_64k: {}", lat.len());
    println!("snapshot_torn: {torn}");
}

/// Three reads and three writes by IEC address, ours against the `process-image` crate.
fn process_image(batches: usize) {
    // An access takes about a nanosecond, below the resolution of a `Duration` per
    // iteration: each iteration is a hundred of them.
    const EACH: usize = 100;
    let (mut buf, mut theirs_buf) = ([0u8; located::BUFFER], [0u8; located::BUFFER]);
    let (ours, theirs) = side_by_side(
        batches,
        200,
        || (0..EACH).for_each(|_| located::ours(&mut buf, &located::ADDRESSES)),
        || (0..EACH).for_each(|_| located::theirs(&mut theirs_buf)),
    );
    // The same accesses with addresses parsed at run time (a tool reading a variable list).
    let parsed = located::TEXTS.map(|t| t.parse::<IecAddress>().expect("address"));
    let runtime = median_per_iter(batches, 200, || {
        (0..EACH).for_each(|_| located::ours(&mut buf, black_box(&parsed)))
    });
    println!(
        "process_image_vs_process_image_crate: {:.2}",
        ratio(ours, theirs)
    );
    println!(
        "process_image_parsed_addresses_vs_process_image_crate: {:.2}",
        ratio(runtime, theirs)
    );
}

/// `cargo check` of a 2,000-field struct, our derive against serde's.
fn derive_check(runs: usize) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/plc-bench");
    let ours = Crate::write(&root, "derive-plc-vars", Flavour::PlcVars, 2000).expect("write");
    let serde = Crate::write(&root, "derive-serde", Flavour::Serde, 2000).expect("write");
    let nested = Crate::write(&root, "derive-nested", Flavour::Nested, 2000).expect("write");
    // The first check of each builds its dependencies (once per machine) and is not counted.
    for c in [&ours, &serde, &nested] {
        if let Err(e) = c.check() {
            fail(&e);
        }
    }
    let (mut a, mut b, mut c) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..runs {
        a.push(ours.check().expect("checked before"));
        b.push(serde.check().expect("checked before"));
        c.push(nested.check().expect("checked before"));
    }
    let median = |mut v: Vec<Duration>| {
        v.sort();
        v[v.len() / 2]
    };
    let (a, b, c) = (median(a), median(b), median(c));
    println!("derive_check_s_2000: {:.1}", a.as_secs_f64());
    println!("derive_check_serde_s_2000: {:.1}", b.as_secs_f64());
    println!("derive_vs_serde_2000: {:.2}", ratio(a, b));
    println!("derive_check_nested_s_2000: {:.1}", c.as_secs_f64());
    println!("derive_nested_vs_flat_2000: {:.2}", ratio(c, a));
}

/// Importing a 10,000-variable JSON file.
fn import_10k() {
    let mut v = serde_json::Map::new();
    for i in 0..10_000 {
        let spec = match i % 4 {
            0 => serde_json::json!({ "type": "u16", "link": format!("ethercat.io{i}.inputs") }),
            1 => serde_json::json!({ "type": "bool", "source": format!("w{}", i - 1), "bit": 3 }),
            2 => {
                serde_json::json!({ "type": "string", "max_length": 32, "description": format!("text {i}") })
            }
            _ => serde_json::json!({ "type": "f64", "nonvolatile": true, "initial": 1.5 }),
        };
        let name = ["w", "b", "s", "r"][i % 4];
        v.insert(format!("{name}{i}"), spec);
    }
    let json = serde_json::json!({ "variables": v }).to_string();
    let t = median_per_iter(3, 1, || {
        black_box(plc_io::import::generate(&json, &Default::default()).expect("import"));
    });
    println!("import_10k_ms: {:.0}", t.as_secs_f64() * 1e3);
}
