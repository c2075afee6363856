//! Time per step of `simulate`, with no trace recorded: the resting box, the
//! 5-box stack (timed over its first 10 s after a 1 s warm-up, while it
//! stands), and piles of spheres on a floor (50 … 2,000 bodies).

#[path = "common/scenes.rs"]
mod common;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("simulate_step");
    g.sample_size(20);
    for id in ["resting-box", "stack-5"] {
        let start = common::scene(id, 60, |_| {});
        g.bench_function(id, |b| {
            b.iter_custom(|iters| common::time_steps(&start, 600, iters))
        });
    }
    for n in [50usize, 200, 1000, 2000] {
        let mut sim = common::pile(n, |_| {});
        g.bench_with_input(BenchmarkId::new("sphere_pile", n), &n, |b, _| {
            b.iter(|| sim.advance().unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
