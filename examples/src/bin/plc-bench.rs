//! The quick benchmark runner: `cargo run --release -p examples --bin plc-bench -- --quick`.
//! Prints one `name: value` line per figure, ratios measured side by side in the same run
//! (machines here are shared and noisy), then `plc-bench: ok`. Method in BENCHMARKS.md.

use examples::bench::gm1k::{Gm1k, Hand1k, IMAGE_SIZE};
use plc_core::{GlobalMemory, ProcessImage};
use plc_io::shm::SharedGlobalMemory;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Median time per iteration of `f` over `batches` batches of `iters` iterations.
fn time(batches: usize, iters: u32, mut f: impl FnMut()) -> Duration {
    let mut t: Vec<Duration> = (0..batches)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..iters {
                f();
            }
            start.elapsed() / iters
        })
        .collect();
    t.sort();
    t[t.len() / 2]
}

/// A 64 KiB image: every word equals `seq` in a consistent snapshot.
#[derive(GlobalMemory, Clone, Debug)]
pub struct Big64k {
    seq: u64,
    data: [u64; 8191],
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("--publisher") {
        publisher(&args[2]);
        return;
    }
    let quick = args.iter().any(|a| a == "--quick");
    let batches = if quick { 15 } else { 61 };
    let segment = format!("plc_bench_{}", std::process::id());

    // The cycle: snapshot in, unpack, pack, image out, seqlock publish.
    let owner = SharedGlobalMemory::<Gm1k>::create(&segment).expect("segment");
    let mut gm = Gm1k::default();
    let mut out = gm.to_image();
    owner.publish_image(&out).expect("publish");
    let framework = time(batches, 2000, || {
        let img = owner.snapshot_image().expect("snapshot");
        gm.load_image(&img);
        gm.unpack_bits();
        gm.pack_bits();
        gm.store_image(&mut out);
        owner.publish_image(black_box(&out)).expect("publish");
    });
    let input = vec![0u8; IMAGE_SIZE];
    let mut output = vec![0u8; IMAGE_SIZE];
    let mut hand = Hand1k::zeroed();
    let handwritten = time(batches, 2000, || {
        hand.load(black_box(&input));
        hand.unpack();
        hand.pack();
        hand.store(&mut output);
        black_box(&output);
    });
    let mut a = vec![1u8; IMAGE_SIZE];
    let mut b = vec![0u8; IMAGE_SIZE];
    let memcpy = time(batches, 2000, || {
        b.copy_from_slice(black_box(&a));
        a.copy_from_slice(black_box(&b));
    });
    drop(owner);
    println!("cycle_1k_ns: {}", framework.as_nanos());
    println!("cycle_1k_handwritten_ns: {}", handwritten.as_nanos());
    println!(
        "cycle_1k_vs_handwritten: {:.2}",
        framework.as_secs_f64() / handwritten.as_secs_f64()
    );
    println!(
        "cycle_1k_vs_memcpy: {:.2}",
        framework.as_secs_f64() / memcpy.as_secs_f64()
    );

    snapshot_latency(&segment, if quick { 3 } else { 10 });
    process_image(batches);
    import_10k();
    println!("plc-bench: ok");
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
    let mut lat = Vec::new();
    let mut torn = 0u64;
    let end = Instant::now() + Duration::from_secs(seconds);
    while Instant::now() < end {
        let t = Instant::now();
        let img = reader.snapshot_image().expect("snapshot");
        lat.push(t.elapsed());
        let g = Big64k::from_image(&img);
        if g.data.iter().any(|&w| w != g.seq) {
            torn += 1;
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    lat.sort();
    let p99 = lat[lat.len() * 99 / 100];
    println!("snapshot_p99_us_64k: {:.1}", p99.as_secs_f64() * 1e6);
    println!("snapshot_count_64k: {}", lat.len());
    println!("snapshot_torn: {torn}");
}

fn process_image(batches: usize) {
    let mut buf = vec![0u8; 64];
    // Addresses parsed once, as a program holds them (the derive makes them constants).
    let a: Vec<plc_core::IecAddress> = ["%IW16", "%IX3.4", "%ID8", "%QW2", "%QX5.1", "%QD12"]
        .iter()
        .map(|t| t.parse().expect("address"))
        .collect();
    let ours = time(batches, 20000, || {
        let mut pi = ProcessImage::new(&mut buf[..]);
        let w: u16 = pi.read(&a[0]).unwrap_or(0);
        let b: bool = pi.read(&a[1]).unwrap_or(false);
        let d: u32 = pi.read(&a[2]).unwrap_or(0);
        let _ = pi.write(&a[3], w.wrapping_add(1));
        let _ = pi.write(&a[4], !b);
        let _ = pi.write(&a[5], d ^ 1);
        black_box(pi.as_bytes());
    });
    let theirs = time(batches, 20000, || {
        let w: u16 = process_image::tag!(&buf[..], W, 16);
        let b: bool = process_image::tag!(&buf[..], X, 3, 4);
        let d: u32 = process_image::tag!(&buf[..], D, 8);
        *process_image::tag_mut!(&mut buf[..], W, 2) = w.wrapping_add(1);
        *process_image::tag_mut!(&mut buf[..], X, 5, 1) = !b;
        *process_image::tag_mut!(&mut buf[..], D, 12) = d ^ 1;
        black_box(&buf);
    });
    println!(
        "process_image_vs_process_image_crate: {:.2}",
        ours.as_secs_f64() / theirs.as_secs_f64()
    );
}

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
    let t = time(3, 1, || {
        black_box(plc_io::import::generate(&json, &Default::default()).expect("import"));
    });
    println!("import_10k_ms: {:.0}", t.as_secs_f64() * 1e3);
}
