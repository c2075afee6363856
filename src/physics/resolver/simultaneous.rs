//! The simultaneous velocity phase (`solver = "lcp"`): every contact's
//! normal impulse at once from one LCP (Newton's law) or two (Poisson's:
//! compression, then e·P_c added, then a correcting LCP if that leaves a
//! contact closing). Each contact's impulse is reported to the observer as
//! one velocity iteration, so the resolver's trace shows what was applied.

use nalgebra::Vector3;

use super::lcp_matrix as matrix;
use super::{desired_of, velocity, Observer, Phase, PhaseOutcome, Resolver};
use crate::physics::lcp::{lemke, Problem, Record, Stage};
use crate::physics::{c, LcpRestitution, Real};

/// Solves one LCP and records it.
fn solve<T: Real>(stage: Stage, a: &[Vec<T>], b: Vec<T>) -> Problem<T> {
    let run = lemke::solve(a, &b);
    Problem {
        stage,
        b,
        pivots: run.pivots,
        result: run.result,
    }
}

/// λ₁ + λ₂ elementwise.
fn add<T: Real>(x: &[T], y: &[T]) -> Vec<T> {
    x.iter().zip(y).map(|(&a, &b)| a + b).collect()
}

/// The impulses of the phase under `law`, with every LCP solved.
fn impulses<T: Real>(
    r: &Resolver<T>,
    a: &[Vec<T>],
    restitutions: &[T],
    problems: &mut Vec<Problem<T>>,
) -> Option<Vec<T>> {
    match r.params.lcp_restitution {
        LcpRestitution::Newton => {
            let b = matrix::newton_b(&r.contacts, r.params.restitution_from);
            problems.push(solve(Stage::Newton, a, b));
            problems[0].result.clone().ok()
        }
        LcpRestitution::Poisson => {
            let b = matrix::compression_b(&r.contacts);
            problems.push(solve(Stage::Compression, a, b.clone()));
            let pc = problems[0].result.clone().ok()?;
            // Restitution phase: P_r = e P_c at every contact.
            let total: Vec<T> = pc
                .iter()
                .zip(restitutions)
                .map(|(&p, &e)| (T::one() + e) * p)
                .collect();
            let w = lemke::residual(a, &b, &total);
            let tol = c::<T>(1e-12) * w.iter().fold(T::one(), |m, &x| m.max(x.abs()));
            if w.iter().all(|&x| x >= -tol) {
                return Some(total);
            }
            problems.push(solve(Stage::Correction, a, w));
            let extra = problems[1].result.clone().ok()?;
            Some(add(&total, &extra))
        }
    }
}

/// Runs the simultaneous velocity phase on `r` (prepared, positions resolved).
pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    let a = matrix::unit_impulse_matrix(&r.contacts, &r.bodies);
    let restitutions = matrix::restitutions(&r.contacts);
    let mut problems = Vec::new();
    let solved = impulses(r, &a, &restitutions, &mut problems);
    let n = r.contacts.len();
    let ok = solved.is_some();
    let lambda = solved.unwrap_or_else(|| vec![T::zero(); n]);
    let from = r.params.restitution_from;
    let mut used = 0;
    for (k, &l) in lambda.iter().enumerate() {
        if l == T::zero() {
            continue;
        }
        obs.before_velocity(used, k, &r.bodies);
        let desired = r.contacts[k].desired;
        let impulse = velocity::apply_impulse(
            &r.contacts[k],
            &mut r.bodies,
            Vector3::new(l, T::zero(), T::zero()),
            None,
        );
        let changes = velocity::BodyChanges::of(&r.contacts[k].bodies, &impulse);
        obs.velocity_taken(used, k, desired, &impulse);
        for (j, cj) in r.contacts.iter_mut().enumerate() {
            let v = velocity::velocity_after(cj, &changes);
            if v != cj.velocity {
                cj.velocity = v;
                let before = cj.desired;
                cj.desired = desired_of(cj, from);
                obs.desired_updated(j, before, cj.desired);
            }
        }
        used += 1;
    }
    // No friction without the normal impulses that bound it.
    let friction = if ok {
        super::lcp_friction::pass(r, &lambda)
    } else {
        None
    };
    let velocities_after = r.contacts.iter().map(|c| c.velocity.x).collect();
    r.lcp = Some(Record {
        restitution: r.params.lcp_restitution,
        rank: lemke::rank(&a),
        matrix: a,
        problems,
        restitutions,
        impulses: lambda,
        velocities_after,
        friction,
    });
    r.finish(Phase::Velocity, used, obs)
}
