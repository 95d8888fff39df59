//! Criterion benchmarks of the cycle and of located access (`cargo bench -p examples`): the
//! same steps `plc-bench` times, with criterion's statistics. Figures and method:
//! BENCHMARKS.md.

use criterion::{Criterion, criterion_group, criterion_main};
use examples::bench::cycle::{FrameworkCycle, HandCycle, MemcpyFloor};
use examples::bench::gm1k::{Gm1k, Hand1k, IMAGE_SIZE};
use examples::bench::located;

fn cycle_1k(c: &mut Criterion) {
    let mut framework =
        FrameworkCycle::<Gm1k>::new(&format!("plc_criterion_{}", std::process::id()))
            .expect("segment");
    let mut hand = HandCycle::<Hand1k>::default();
    let mut floor = MemcpyFloor::new(IMAGE_SIZE);
    let mut g = c.benchmark_group("cycle_1k");
    g.bench_function("framework", |b| b.iter(|| framework.step()));
    // The conversions and the publish of the runtime's cycle (its loops over runs included).
    g.bench_function("runtime_outputs", |b| b.iter(|| framework.runtime_step()));
    // Each part alone: the loads, bit moves and stores the derive generates.
    for (name, part) in FrameworkCycle::<Gm1k>::parts() {
        g.bench_function(format!("framework_{name}"), |b| {
            b.iter(|| part(&mut framework))
        });
    }
    g.bench_function("handwritten", |b| b.iter(|| hand.step()));
    g.bench_function("memcpy", |b| b.iter(|| floor.step()));
    g.finish();
}

fn process_image(c: &mut Criterion) {
    let (mut ours, mut theirs) = ([0u8; located::BUFFER], [0u8; located::BUFFER]);
    let mut g = c.benchmark_group("process_image");
    g.bench_function("plc_core", |b| {
        b.iter(|| located::ours(&mut ours, &located::ADDRESSES))
    });
    g.bench_function("process_image_crate", |b| {
        b.iter(|| located::theirs(&mut theirs))
    });
    g.finish();
}

criterion_group!(benches, cycle_1k, process_image);
criterion_main!(benches);
