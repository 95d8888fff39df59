//! Criterion benchmarks of the cycle and of located access (`cargo bench -p plc-bench`): the
//! same steps `plc-bench` times, with criterion's statistics. Figures and method:
//! BENCHMARKS.md.

use criterion::{Criterion, criterion_group, criterion_main};
use plc_bench::cycle::{FrameworkCycle, HandCycle, MemcpyFloor, runtime_cycles};
use plc_bench::gm1k::{Gm1k, Hand1k, IMAGE_SIZE};
use plc_bench::located;

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

/// The real `Runtime`'s cycles: on `Gm1k` without I/O (what `cycle_1k_runtime_vs_memcpy`
/// times), and the framework's own time per cycle on the in-process simulated bus (what
/// `bus_framework_us_per_cycle` times over the veth pair). Each sample starts a runtime (and
/// the bus) afresh; only its cycles are timed.
fn runtime(c: &mut Criterion) {
    let segment = format!("plc_criterion_rt_{}", std::process::id());
    let mut g = c.benchmark_group("runtime");
    g.bench_function("gm1k_cycle", |b| {
        b.iter_custom(|iters| runtime_cycles::<Gm1k>(&segment, iters).expect("runtime"))
    });
    // A bring-up takes a quarter of a second: each iteration stands for a thousand cycles,
    // and the figure is the framework's time per cycle.
    const CYCLES: u32 = 1000;
    g.sample_size(10)
        .warm_up_time(std::time::Duration::from_millis(500))
        .measurement_time(std::time::Duration::from_secs(5));
    g.bench_function("bus_inproc_framework", |b| {
        b.iter_custom(|iters| {
            let cycles = iters as usize * CYCLES as usize;
            plc_bench::bus::framework_time_in_process(cycles).expect("bus") / CYCLES
        })
    });
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

criterion_group!(benches, cycle_1k, runtime, process_image);
criterion_main!(benches);
