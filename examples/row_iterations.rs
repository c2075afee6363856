//! How the iterations the resolver needs grow with the length of a row of
//! touching spheres on a floor (`physics::resolver::row`), when the
//! iteration limit is raised so that every phase runs until nothing is above
//! its epsilon; and what the default limit (8 × contacts) leaves.
//!
//! `cargo run --release --features measure --example row_iterations [N …]`

use std::time::Instant;

use contact_lab::physics::params::ResolverParams;
use contact_lab::physics::resolver::{row::sphere_row, Implementation, Resolver, Silent};

fn main() {
    let lengths: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("a row length"))
        .collect();
    let lengths = if lengths.is_empty() {
        vec![5, 10, 20, 50, 100, 200, 500, 1000, 2000]
    } else {
        lengths
    };
    println!("| spheres | contacts | position iterations to ε | × contacts | velocity iterations to ε | × contacts | default limit: position used | deepest left | velocity used | largest Δv left | time (unlimited) |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for n in lengths {
        let world = sphere_row::<f64>(n);
        let contacts = world.contacts.len();
        let unlimited = ResolverParams {
            position_iterations: Some(1_000_000_000),
            velocity_iterations: Some(1_000_000_000),
            ..ResolverParams::default()
        };
        let start = Instant::now();
        let (_, [p, v]) =
            Resolver::resolve(&world, &unlimited, Implementation::Indexed, &mut Silent);
        let seconds = start.elapsed().as_secs_f64();
        let (_, [pd, vd]) = Resolver::resolve(
            &world,
            &ResolverParams::default(),
            Implementation::Indexed,
            &mut Silent,
        );
        println!(
            "| {n} | {contacts} | {} | {:.1} | {} | {:.1} | {} | {:.4} | {} | {:.4} | {:.3} s |",
            p.iterations_used,
            p.iterations_used as f64 / contacts as f64,
            v.iterations_used,
            v.iterations_used as f64 / contacts as f64,
            pd.iterations_used,
            pd.max_after,
            vd.iterations_used,
            vd.max_after,
            seconds
        );
    }
}
