//! An exhaustive scan behind advise's measure-layer bound on
//! mass-ratio-stack (docs/study.md, "Its cost"): every configuration of dt
//! (1/30 … 1/240) × budget (1 … converged) × both epsilons (0.1 … 10⁻⁴) ×
//! rollback × sleep (off, body, island) × solver (deepest-first, sequential
//! impulses cold or warm) × ccd (none, conservative) × relaxation (0.5, 1) ×
//! float (f32, f64), 55,296 configurations, the other knobs at the
//! reference's. Each runs for the scene's advise length, stopped once its
//! work passes `CAP` per simulated second; those that finish are listed when
//! their run's error meets the target at the end or at every step, with
//! the error at the end, the settled error (advise's per-run measure: the
//! largest over the run's last tenth, the end's included) and the per-step
//! error (the largest over the run). Prints the cheapest by each measure.
//!
//! `cargo run --release --features measure --example advise_scan -- [SCENE] [TARGET] [CAP]`
//! (defaults: mass-ratio-stack, 0.01 m, 2120).
use contact_lab::lesson::Lesson;
use contact_lab::study::advise::{cost, run_of};
use contact_lab::study::{grid, run};

/// One value of a scanned dimension: the knobs it sets.
type Setting = &'static [(&'static str, &'static str)];

fn main() {
    let arg = |i: usize| std::env::args().nth(i);
    let id = arg(1).unwrap_or_else(|| "mass-ratio-stack".into());
    let target: f64 = arg(2).map_or(0.01, |s| s.parse().expect("a target in m"));
    let cap: f64 = arg(3).map_or(2120.0, |s| s.parse().expect("a cost"));
    let l = Lesson::load(&id).expect("an embedded scene");
    let (seconds, solver) = run_of(&l).expect("a scene");
    let reference = grid::reference(&grid::default_config(&l).unwrap(), solver);
    let trajectory = run::trajectory(&l, &reference, seconds);
    let end = run::measure(&l, &reference, seconds).positions;
    let dims: [(&str, &[Setting]); 10] = [
        (
            "dt",
            &[
                &[("dt", "1/30")],
                &[("dt", "1/60")],
                &[("dt", "1/120")],
                &[("dt", "1/240")],
            ],
        ),
        (
            "budget",
            &[
                &[("budget", "1")],
                &[("budget", "2")],
                &[("budget", "4")],
                &[("budget", "8")],
                &[("budget", "16")],
                &[("budget", "converged")],
            ],
        ),
        (
            "position_epsilon",
            &[
                &[("position_epsilon", "0.1")],
                &[("position_epsilon", "0.01")],
                &[("position_epsilon", "0.001")],
                &[("position_epsilon", "0.0001")],
            ],
        ),
        (
            "velocity_epsilon",
            &[
                &[("velocity_epsilon", "0.1")],
                &[("velocity_epsilon", "0.01")],
                &[("velocity_epsilon", "0.001")],
                &[("velocity_epsilon", "0.0001")],
            ],
        ),
        (
            "rollback",
            &[&[("rollback", "projection")], &[("rollback", "rollback")]],
        ),
        (
            "sleep",
            &[
                &[("sleep", "false")],
                &[("sleep", "true"), ("sleep_mode", "body")],
                &[("sleep", "true"), ("sleep_mode", "island")],
            ],
        ),
        (
            "solver",
            &[
                &[("solver", "deepest-first"), ("warm_start", "false")],
                &[("solver", "sequential-impulse"), ("warm_start", "false")],
                &[("solver", "sequential-impulse"), ("warm_start", "true")],
            ],
        ),
        ("ccd", &[&[("ccd", "none")], &[("ccd", "conservative")]]),
        (
            "relaxation",
            &[&[("relaxation", "0.5")], &[("relaxation", "1")]],
        ),
        (
            "precision",
            &[&[("precision", "f32")], &[("precision", "f64")]],
        ),
    ];
    let total: usize = dims.iter().map(|(_, v)| v.len()).product();
    let limit = (cap * seconds * (1.0 + 1e-6)).ceil() as usize;
    let started = std::time::Instant::now();
    let (mut finished, mut seen) = (0, std::collections::HashSet::<String>::new());
    let mut found: Vec<(f64, f64, f64, f64, String)> = Vec::new();
    for mut k in 0..total {
        let mut c = reference;
        let mut label = Vec::new();
        for (_, values) in &dims {
            let sets = values[k % values.len()];
            k /= values.len();
            for (name, v) in sets {
                grid::set(&mut c, name, v).expect("a value the knob takes");
            }
            label.push(
                sets.iter()
                    .map(|(n, v)| format!("{n}={v}"))
                    .collect::<Vec<_>>()
                    .join(" "),
            );
        }
        // Settings that coincide (sleep_mode without sleep, …) run once.
        if !seen.insert(format!("{c:?}")) {
            continue;
        }
        let m = run::measure_against(&l, &c, seconds, limit, Some(&trajectory));
        if m.capped || m.failure.is_some() {
            continue;
        }
        finished += 1;
        let error = run::rms_distance(&m.positions, &end);
        // The settled error, advise's per-run measure: the end's or the
        // last tenth's, the larger.
        let settled = error.max(m.settle_error);
        if error <= target || m.step_error <= target {
            found.push((
                cost(&m, seconds),
                error,
                settled,
                m.step_error,
                label.join(" "),
            ));
        }
    }
    found.sort_by(|a, b| a.0.total_cmp(&b.0));
    println!(
        "{id}: {} distinct configurations of {total}, {finished} finished under cost {cap} in {:.0} s",
        seen.len(),
        started.elapsed().as_secs_f64()
    );
    println!(
        "{:>7} {:>9} {:>9} {:>9}  meets {target} m at the end / settled (advise per run) / by step",
        "cost", "end", "settled", "step"
    );
    for (cost, e, settled, s, label) in &found {
        println!(
            "{cost:>7.0} {e:>9.2e} {settled:>9.2e} {s:>9.2e}  {}{}{}  {label}",
            if *e <= target { "E" } else { "-" },
            if *settled <= target { "R" } else { "-" },
            if *s <= target { "S" } else { "-" }
        );
    }
    for (name, ok) in [
        ("at the end", 1),
        ("settled (advise --per run)", 2),
        ("at every step (advise --per step)", 3),
    ] {
        let best = found.iter().find(|f| [f.1, f.2, f.3][ok - 1] <= target);
        println!(
            "cheapest within {target} m {name}: {}",
            best.map_or("none under the cap".into(), |f| format!(
                "{:.0}  {}",
                f.0, f.4
            ))
        );
    }
}
