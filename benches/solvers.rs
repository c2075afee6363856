//! The lecture's deepest-first resolver against sequential impulses (with
//! and without warm start), µs per simulate step at the same budget
//! (8 contact visits per contact per phase): the 5-box stack and a pile of
//! 200 spheres, sleep off so every step does the full work. The stack is
//! timed over its first 10 s after a 1 s warm-up, started again from there,
//! so a standing stack is timed (cold sequential impulses let it fall
//! within 5 s: that figure is a falling stack's).

#[path = "common/scenes.rs"]
mod common;

use contact_lab::physics::{ResolverParams, Solver};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};

const SOLVERS: [(&str, Solver, bool); 3] = [
    ("deepest_first", Solver::DeepestFirst, false),
    ("sequential_impulse", Solver::SequentialImpulse, false),
    ("sequential_impulse+warm", Solver::SequentialImpulse, true),
];

fn with_solver(p: &mut ResolverParams, solver: Solver, warm: bool) {
    p.solver = solver;
    p.warm_start = warm;
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("solver_step");
    g.sample_size(20);
    for (name, solver, warm) in SOLVERS {
        let start = common::scene("stack-5", 60, |p| with_solver(p, solver, warm));
        g.bench_with_input(BenchmarkId::new("stack-5", name), &name, |b, _| {
            b.iter_custom(|iters| common::time_steps(&start, 600, iters))
        });
        let mut sim = common::pile(200, |p| with_solver(p, solver, warm));
        g.bench_with_input(BenchmarkId::new("sphere_pile_200", name), &name, |b, _| {
            b.iter(|| sim.advance().unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
