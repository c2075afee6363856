//! Cost of one contact: bare stage maths (`solve_stages`, f64 and f32; and
//! `solve_stages_into` a `Stages` the loop holds, as a hot loop would call it),
//! the stages with their physical checks (`solve`), against the full worked
//! solution with its trace, and the friction path against the frictionless
//! one.

use std::hint::black_box;

use contact_lab::lesson::Lesson;
use contact_lab::physics::solve::{solve, solve_stages, solve_stages_into, Stages};
use criterion::{criterion_group, criterion_main, Criterion};

fn bench(c: &mut Criterion) {
    let cases = [
        ("frictionless", "lecture-2", 0),
        ("friction-sticks", "friction-cube", 0),
        ("friction-slides", "friction-cube", 1),
        ("projection", "lecture-3", 0),
    ];
    for (name, id, k) in cases {
        let lesson = Lesson::load(id).unwrap();
        let p64 = lesson.problem::<f64>(k);
        let p32 = lesson.problem::<f32>(k);
        let mut group = c.benchmark_group(name);
        group.bench_function("stages_f64", |b| b.iter(|| solve_stages(black_box(&p64))));
        let mut held = Stages::empty();
        group.bench_function("stages_into_f64", |b| {
            b.iter(|| solve_stages_into(black_box(&p64), black_box(&mut held)))
        });
        group.bench_function("stages_f32", |b| b.iter(|| solve_stages(black_box(&p32))));
        group.bench_function("checked_f64", |b| b.iter(|| solve(black_box(&p64))));
        group.bench_function("trace_f64", |b| {
            b.iter(|| contact_lab::worked_solution(black_box(&lesson), k))
        });
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(50).measurement_time(std::time::Duration::from_secs(2)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
