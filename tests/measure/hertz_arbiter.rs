//! Finite stiffness as the arbiter (issue 43): the row of three balls and
//! the stacked drop, resolved by the compliant reference (Hertz contacts,
//! k·δ^1.5, RK4 through the impact, src/physics/lcp/hertz.rs) with the gap
//! before the second contact varied, against the two rigid answers (the
//! lecture's sequence and the LCP's simultaneous one). Printed: the
//! velocities after, the error of each rigid answer against the
//! reference (largest component), and where the reference falls between
//! them (0: the sequence, 1: the simultaneous answer; the projection of
//! v_hertz - v_seq on v_sim - v_seq). `--nocapture` for the table.

use contact_lab::physics::lcp::hertz::Chain;

const K: f64 = 1e7;
const H: f64 = 1e-7;
const GAPS: [f64; 5] = [0.0, 1e-5, 1e-4, 1e-3, 1e-2];

fn fraction(h: &[f64], seq: &[f64], sim: &[f64]) -> f64 {
    let d: Vec<f64> = sim.iter().zip(seq).map(|(a, b)| a - b).collect();
    let num: f64 = h
        .iter()
        .zip(seq)
        .zip(&d)
        .map(|((h, s), d)| (h - s) * d)
        .sum();
    num / d.iter().map(|d| d * d).sum::<f64>()
}

fn error(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

fn list(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:7.4}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// One row of the table; returns the fraction.
fn report(what: &str, gap: f64, chain: &Chain, movable: usize, seq: &[f64], sim: &[f64]) -> f64 {
    let out = chain.impact(H, 5_000_000);
    assert!(out.ended, "{what} gap {gap}: the impact did not end");
    let p0 = chain.momentum(&chain.velocity);
    if chain.inverse_mass.iter().all(|&w| w > 0.0) {
        let p1 = chain.momentum(&out.velocity);
        assert!(
            (p1 - p0).abs() < 1e-9 * p0.abs(),
            "{what}: momentum {p0} -> {p1}"
        );
    }
    let e0 = chain.energy(&chain.position, &chain.velocity);
    // The initial positions overlap nowhere: this is the kinetic energy after.
    let e1 = chain.energy(&chain.position, &out.velocity);
    assert!((e1 - e0).abs() < 1e-6 * e0, "{what}: energy {e0} -> {e1}");
    let v = &out.velocity[out.velocity.len() - movable..];
    let s = fraction(v, seq, sim);
    println!(
        "{what:<16} {gap:>8.0e}  [{}]  seq err {:.4}  sim err {:.4}  between {s:6.3}  ({} steps)",
        list(v),
        error(v, seq),
        error(v, sim),
        out.steps
    );
    s
}

#[test]
fn hertz_between_the_sequence_and_the_simultaneous_answer() {
    println!("k = {K:e} N/m^1.5, h = {H:e} s; the gap is before the second contact");
    println!("scene            gap       velocities after           errors against Hertz   0 = sequence, 1 = simultaneous");
    let mut row = vec![];
    for gap in GAPS {
        let chain = Chain {
            inverse_mass: vec![1.0; 3],
            position: vec![0.0, 1.0, 2.0 + gap],
            velocity: vec![1.0, 0.0, 0.0],
            rest: vec![1.0, 1.0],
            stiffness: K,
        };
        let sim = [-1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0];
        row.push(report("row of 3", gap, &chain, 3, &[0.0, 0.0, 1.0], &sim));
    }
    let mut stacks = vec![];
    for r in [0.1, 0.5] {
        for gap in GAPS {
            // Along y: the floor (a wall), the bottom ball touching it, the
            // top ball `gap` above the bottom one; both falling at 1 m/s.
            let chain = Chain {
                inverse_mass: vec![0.0, 1.0, 1.0 / r],
                position: vec![0.0, 0.5, 1.5 + gap],
                velocity: vec![0.0, -1.0, -1.0],
                rest: vec![0.5, 1.0],
                stiffness: K,
            };
            let top_seq = (3.0 - r) / (1.0 + r);
            let bottom_seq = seq_bottom(r);
            let what = format!("stack r = {r}");
            stacks.push(report(
                &what,
                gap,
                &chain,
                2,
                &[bottom_seq, top_seq],
                &[1.0, 1.0],
            ));
        }
    }
    // The widest gap (far wider than the compression, about 1.3e-3 m here)
    // makes the impacts one at a time: the sequence.
    for s in [
        row[GAPS.len() - 1],
        stacks[GAPS.len() - 1],
        stacks[2 * GAPS.len() - 1],
    ] {
        assert!(s.abs() < 0.02, "{s}");
    }
    // Touching, the reference is not the sequence; each gap moves it toward the sequence.
    for w in [&row[..], &stacks[..GAPS.len()], &stacks[GAPS.len()..]] {
        assert!(w[0] > 0.1, "{w:?}");
        assert!(w.windows(2).all(|p| p[1] <= p[0] + 1e-9), "{w:?}");
    }
}

/// The bottom ball after the sequence (floor, pair, then the floor again
/// while it closes): the rigid deepest-first answer.
fn seq_bottom(r: f64) -> f64 {
    // After the floor: bottom +1. The pair: bottom (1 - 3r)/(1 + r).
    let b = (1.0 - 3.0 * r) / (1.0 + r);
    // Closing on the floor again: it bounces (e = 1).
    b.abs()
}
