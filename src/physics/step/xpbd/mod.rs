//! XPBD, extended position based dynamics (Müller, Macklin, Chentanez,
//! Jeschke, Kim 2020, "Detailed rigid body simulation with extended
//! position based dynamics"), `solver = "xpbd"`. A step is `substeps`
//! substeps of h = Δt / substeps, each:
//!
//! 1. integrate: v += h g (damping), x̃ = x + h v, q̃ = q + ½h[ω, 0]q;
//! 2. one position iteration over the contacts ([`passes::position`]):
//!    a penetrating contact's Δλ_n = (−C − α̃λ_n)/(w₁ + w₂ + α̃), α̃ = α/h²;
//!    static friction as a position constraint on the anchors' tangential
//!    move, applied only while λ_t ≤ μ_s λ_n;
//! 3. velocities from positions: v = (x − x_prev)/h, ω = 2 vec(q q_prev⁻¹)/h;
//! 4. the velocity pass ([`passes::velocity`]): dynamic friction
//!    (the printed or the corrected formula, [`DynamicFriction`]) and
//!    restitution (e = 0 below 2|g|h) on the contacts active this substep.
//!
//! The contacts are generated once per step (as Solver2D's XPBD does): each
//! keeps its point as an anchor on both bodies, and its separation moves
//! with the anchors. The solver integrates the bodies itself: the stepper
//! skips its own velocity integration and position update for it.
//! - `body.rs`: the working bodies (poses, masses, the substep's start);
//! - `passes.rs`: the position and the velocity pass of one contact;
//! - `record.rs`: what a traced step keeps of each substep.

mod body;
mod passes;
pub mod record;

use nalgebra::Vector3;

use crate::physics::resolver::{Phase, PhaseOutcome};
use crate::physics::{c, Real, World};
use body::Bodies;
pub use record::{ContactRecord, SubstepRecord};

/// Which dynamic-friction formula the velocity pass applies (the erratum
/// `errata` lists, measured on a sliding box).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DynamicFriction {
    /// The paper's (eq. 30): Δv = −v_t/|v_t| · min(h μ_d |f_n|, |v_t|) with
    /// f_n = λ_n/h²: h μ_d |f_n| = μ_d λ_n / h is an impulse (kg·m/s), not
    /// a speed; the deceleration comes out as μ_d g × (the body's mass in kg).
    Printed,
    /// Solver2D's correction (Erin Catto): the impulse times the
    /// generalized inverse mass, μ_d λ_n (w₁ + w₂)/h, a speed: deceleration μ_d g.
    #[default]
    Corrected,
}

/// XPBD's own switches (not knobs: the erratum's experiment sets them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct XpbdOptions {
    /// The contacts' compliance α (m/N; 0 = rigid, as the paper's contacts
    /// and Solver2D's): α̃ = α/h².
    pub compliance: f64,
    pub dynamic_friction: DynamicFriction,
}

impl Default for XpbdOptions {
    fn default() -> Self {
        XpbdOptions {
            compliance: 0.0,
            dynamic_friction: DynamicFriction::Corrected,
        }
    }
}

/// What a step needs beyond the world: Δt, the substeps, gravity and damping.
#[derive(Debug, Clone, Copy)]
pub struct StepInput<'a, T: Real> {
    pub dt: T,
    pub substeps: usize,
    pub gravity: Vector3<T>,
    pub linear_damping: T,
    pub angular_damping: T,
    /// Which bodies move (movable and awake); the others are as the world.
    pub moving: &'a [bool],
    pub options: XpbdOptions,
    /// The position phase's epsilon (reported, not used to stop).
    pub position_epsilon: f64,
    pub velocity_epsilon: f64,
}

/// Advances `world` (its contacts generated at the step's start) one XPBD
/// step: positions and velocities of the moving bodies. `record` receives
/// each substep when given. The two outcomes stand for the position and
/// the velocity passes summed over the substeps.
pub fn step<T: Real>(
    world: &mut World<T>,
    input: &StepInput<'_, T>,
    mut record: Option<&mut Vec<SubstepRecord>>,
) -> [PhaseOutcome<T>; 2] {
    let n = input.substeps.max(1);
    let h = input.dt / c::<T>(n as f64);
    let mut bodies = Bodies::of_world(world, input.moving);
    let mut contacts = passes::anchors(world, &bodies);
    let alpha_tilde: T = c::<T>(input.options.compliance) / (h * h);
    let max_before = contacts
        .iter()
        .fold(T::zero(), |m, k| m.max(k.penetration0));
    let mut visits = [0usize; 2];
    let kept = super::integrate::Kept::over(input.linear_damping, input.angular_damping, h);
    for s in 0..n {
        bodies.predict(&input.gravity, &kept, h);
        let mut sub = record
            .as_ref()
            .map(|_| SubstepRecord::new(s + 1, to(h), to(alpha_tilde)));
        for (k, contact) in contacts.iter_mut().enumerate() {
            let r = passes::position(contact, &mut bodies, alpha_tilde, h);
            if r.is_some() {
                visits[0] += 1;
            }
            if let (Some(sub), Some(r)) = (sub.as_mut(), r) {
                sub.contacts.push(ContactRecord::of_position(k, &r));
            }
        }
        bodies.velocities_from_positions(h);
        let g = input.gravity.norm();
        for (k, contact) in contacts.iter_mut().enumerate() {
            let v = passes::velocity(contact, &mut bodies, h, g, input.options.dynamic_friction);
            if v.is_some() {
                visits[1] += 1;
            }
            if let (Some(sub), Some(v)) = (sub.as_mut(), v) {
                if let Some(row) = sub.contacts.iter_mut().find(|r| r.contact == k) {
                    row.add_velocity(&v);
                }
            }
        }
        if let (Some(rec), Some(sub)) = (record.as_mut(), sub) {
            rec.push(sub);
        }
    }
    bodies.write_back(world, &input.gravity);
    let max_after = contacts
        .iter()
        .map(|k| passes::penetration_now(k, &bodies))
        .enumerate()
        .fold((T::zero(), 0), |m, (k, d)| if d > m.0 { (d, k) } else { m });
    let limit = n.saturating_mul(contacts.len());
    let outcome = |phase, used, epsilon: f64, before: T, after: (T, usize)| PhaseOutcome {
        phase,
        iterations_used: used,
        iteration_limit: limit,
        epsilon: c(epsilon),
        max_before: before,
        max_after: after.0,
        max_after_contact: after.1,
        limit_reached: false,
    };
    [
        outcome(
            Phase::Position,
            visits[0],
            input.position_epsilon,
            max_before,
            max_after,
        ),
        outcome(
            Phase::Velocity,
            visits[1],
            input.velocity_epsilon,
            T::zero(),
            (T::zero(), 0),
        ),
    ]
}

fn to<T: Real>(x: T) -> f64 {
    crate::physics::to_f64(x)
}
