//! Criterion benchmarks of the cycle and of located access (`cargo bench -p examples`): the
//! same steps `plc-bench` times, with criterion's statistics. Figures and method:
//! BENCHMARKS.md.

use criterion::{Criterion, criterion_group, criterion_main};
use examples::bench::cycle::{FrameworkCycle, HandCycle, MemcpyFloor};
use examples::bench::gm1k::{Gm1k, Hand1k, IMAGE_SIZE};
use plc_core::{IecAddress, ProcessImage};
use std::hint::black_box;

fn cycle_1k(c: &mut Criterion) {
    let mut framework =
        FrameworkCycle::<Gm1k>::new(&format!("plc_criterion_{}", std::process::id()))
            .expect("segment");
    let mut hand = HandCycle::<Hand1k>::default();
    let mut floor = MemcpyFloor::new(IMAGE_SIZE);
    let mut g = c.benchmark_group("cycle_1k");
    g.bench_function("framework", |b| b.iter(|| framework.step()));
    g.bench_function("handwritten", |b| b.iter(|| hand.step()));
    g.bench_function("memcpy", |b| b.iter(|| floor.step()));
    g.finish();
}

fn process_image(c: &mut Criterion) {
    let addresses: Vec<IecAddress> = ["%IW16", "%IX3.4", "%ID8", "%QW2", "%QX5.1", "%QD12"]
        .iter()
        .map(|t| t.parse().expect("address"))
        .collect();
    let mut buf = vec![0u8; 64];
    let mut g = c.benchmark_group("process_image");
    g.bench_function("plc_core", |b| {
        b.iter(|| {
            let mut pi = ProcessImage::new(&mut buf[..]);
            let w: u16 = pi.read(&addresses[0]).unwrap_or(0);
            let x: bool = pi.read(&addresses[1]).unwrap_or(false);
            let d: u32 = pi.read(&addresses[2]).unwrap_or(0);
            let _ = pi.write(&addresses[3], w.wrapping_add(1));
            let _ = pi.write(&addresses[4], !x);
            let _ = pi.write(&addresses[5], d ^ 1);
            black_box(pi.as_bytes());
        })
    });
    let mut theirs = vec![0u8; 64];
    g.bench_function("process_image_crate", |b| {
        b.iter(|| {
            let buf = &mut theirs;
            let w: u16 = process_image::tag!(&buf[..], W, 16);
            let x: bool = process_image::tag!(&buf[..], X, 3, 4);
            let d: u32 = process_image::tag!(&buf[..], D, 8);
            *process_image::tag_mut!(&mut buf[..], W, 2) = w.wrapping_add(1);
            *process_image::tag_mut!(&mut buf[..], X, 5, 1) = !x;
            *process_image::tag_mut!(&mut buf[..], D, 12) = d ^ 1;
            black_box(&buf);
        })
    });
    g.finish();
}

criterion_group!(benches, cycle_1k, process_image);
criterion_main!(benches);
