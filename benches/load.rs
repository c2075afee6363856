//! Loading a lesson of many contacts (issue 23: `resolve` with 10⁵ contacts
//! loaded worse than linearly, each contact's overflow check building the
//! whole world). A chain of N bodies, each touching the next: parsing and
//! validating 1,000, 4,000 and 16,000 contacts; the time per contact should
//! stay flat (criterion's elements/s).

use std::fmt::Write;
use std::hint::black_box;
use std::time::Duration;

use contact_lab::lesson::validate::parse;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

/// A lesson of `n` contacts between `n + 1` bodies in a row.
fn chain(n: usize) -> String {
    let mut s = String::from(
        "id = \"chain\"\ntitle = \"chain\"\nsource = \"bench\"\nsummary = \"bench\"\n",
    );
    for i in 0..=n {
        let _ = write!(
            s,
            "\n[[body]]\nname = \"b{i}\"\nmass = 1.0\ninertia = [[1,0,0],[0,1,0],[0,0,1]]\nposition = [{i}.0, 0, 0]\nvelocity = [0, -1, 0]\n"
        );
    }
    for i in 0..n {
        let _ = write!(
            s,
            "\n[[contact]]\nbodies = [\"b{i}\", \"b{}\"]\npoint = [{i}.5, 0, 0]\nnormal = [-1, 0, 0]\npenetration = 0.01\nrestitution = 0.5\nfriction = 0.0\n",
            i + 1
        );
    }
    s
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("load_chain");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(3));
    for n in [1_000usize, 4_000, 16_000] {
        let text = chain(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(format!("{n}_contacts"), |b| {
            b.iter(|| black_box(parse("chain.toml", black_box(&text)).expect("valid")))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
