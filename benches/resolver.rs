//! The resolver on rows of 20, 200, 2000 and 6000 touching spheres on a floor
//! (39, 399, 3999 and 11,999 contacts), default limits (8 × contacts per
//! phase): the scan (the lecture's loop) against the indexed implementation.
//! Each case times prepare + both phases in a resolver whose storage is
//! reused from run to run (as an engine resolving every frame would use it,
//! and as the reference engine works in the caller's contact array), so no
//! allocation is timed; the throughput is the number of iterations (both
//! phases), so criterion's elements/s gives the time per iteration. Before timing, each row is resolved by both implementations and
//! the results are checked to be identical.

use std::hint::black_box;
use std::time::Duration;

use contact_lab::physics::params::ResolverParams;
use contact_lab::physics::resolver::{row::sphere_row, Implementation, Resolver, Silent};
use criterion::{criterion_group, criterion_main, Criterion, SamplingMode, Throughput};

fn bench(c: &mut Criterion) {
    let params = ResolverParams::default();
    for n in [20usize, 200, 2000, 6000] {
        let world = sphere_row::<f64>(n);
        let (scan, scan_out) =
            Resolver::resolve(&world, &params, Implementation::Scan, &mut Silent);
        let (indexed, indexed_out) =
            Resolver::resolve(&world, &params, Implementation::Indexed, &mut Silent);
        assert_eq!(scan_out, indexed_out, "row of {n}: same phases");
        assert_eq!(scan.bodies, indexed.bodies, "row of {n}: same bodies");
        assert_eq!(
            scan.contacts, indexed.contacts,
            "row of {n}: same bookkeeping"
        );
        let iterations = (scan_out[0].iterations_used + scan_out[1].iterations_used) as u64;
        eprintln!(
            "row of {n}: {} contacts, {} position + {} velocity iterations (limits {}), deepest penetration left {:.4}",
            world.contacts.len(),
            scan_out[0].iterations_used,
            scan_out[1].iterations_used,
            scan_out[0].iteration_limit,
            scan_out[0].max_after
        );
        let mut group = c.benchmark_group(format!("resolver_row_{n}"));
        group.throughput(Throughput::Elements(iterations));
        if n >= 2000 {
            // Seconds per scan run: the fewest samples criterion allows.
            group.sample_size(10);
            group.sampling_mode(SamplingMode::Flat);
            group.warm_up_time(Duration::from_millis(1));
            group.measurement_time(Duration::from_secs(1));
        }
        for implementation in [Implementation::Scan, Implementation::Indexed] {
            let mut r = Resolver::prepare(&world, &params);
            group.bench_function(implementation.name(), |b| {
                b.iter(|| {
                    r.prepare_again(black_box(&world), &params);
                    let p = r.position_phase(implementation, &mut Silent);
                    let v = r.velocity_phase(implementation, &mut Silent);
                    black_box((p, v))
                })
            });
        }
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(Duration::from_secs(2)).warm_up_time(Duration::from_millis(300));
    targets = bench
}
criterion_main!(benches);
