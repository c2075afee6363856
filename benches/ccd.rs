//! Cost per step of each continuous-detection mode (`ccd` = none,
//! bisection, conservative): the bullet's first step (the one with the
//! collision: a tunnelling audit without ccd, a search and a sub-step with
//! it), and study scenes where nothing tunnels (the swept broad phase and
//! the searches of pairs whose movement bounds meet).

#[path = "common/scenes.rs"]
#[allow(dead_code)] // the pile of spheres is the other benches'
mod common;

use contact_lab::knobs::Choice;
use contact_lab::physics::step::ccd_mode::Ccd;
use contact_lab::physics::step::Simulation;
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion};

fn with_ccd(id: &str, warm: usize, ccd: Ccd) -> Simulation<f64> {
    let mut sim = common::scene(id, 0, |_| {});
    sim.params.ccd = ccd;
    for _ in 0..warm {
        sim.advance().unwrap();
    }
    sim
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("ccd_step");
    g.sample_size(20);
    for ccd in Ccd::ALL {
        let bullet = with_ccd("bullet-wall", 0, ccd);
        g.bench_with_input(
            BenchmarkId::new("bullet_first_step", ccd.name()),
            &ccd,
            |b, _| {
                b.iter_batched(
                    || bullet.clone(),
                    |mut sim| sim.advance().unwrap(),
                    BatchSize::SmallInput,
                )
            },
        );
        for id in ["stack-5", "sphere-row-20", "ball-drop"] {
            let start = with_ccd(id, 30, ccd);
            g.bench_with_input(BenchmarkId::new(id, ccd.name()), &ccd, |b, _| {
                b.iter_custom(|iters| common::time_steps(&start, 120, iters))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
