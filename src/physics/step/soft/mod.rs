//! The soft step (`solver = "soft-step"`), in Box2D v3's `b2SolverStage`
//! order: prepare once; per substep integrate velocities, warm start, solve
//! with bias, integrate positions, relax (solve without bias,
//! `relax_iterations` times); then a restitution pass from the pre-solve
//! normal velocities; store the impulses for the next step's warm start.
//!
//! - `prepare.rs`: one contact's constraint (anchors, tangents, masses);
//! - `solve.rs`: the passes over the constraints;
//! - `warm.rs`: last step's impulses matched to this step's contacts;
//! - `trace.rs`: what a traced step records (each contact's coefficients).

mod prepare;
mod solve;
pub mod trace;
mod warm;

use nalgebra::Matrix3;

use super::integrate::{integrate_position, integrate_velocity_kept, Kept, Loads};
use crate::physics::params::{SimParams, Softness};
use crate::physics::{c, to_f64, Real, World};
pub use prepare::SoftContact;
pub use trace::SoftTrace;

/// The soft step's storage, kept from step to step (no allocation per
/// substep; the vectors grow to the largest step and stay).
#[derive(Debug, Clone)]
pub struct SoftSolver<T: Real> {
    /// This step's constraints, one per contact (the world's order).
    pub contacts: Vec<SoftContact<T>>,
    /// Each body's world inverse inertia at the step's start (zero when it
    /// does not move this step) and whether it moves.
    inverse_inertia: Vec<Matrix3<T>>,
    moving: Vec<bool>,
    /// Last step's impulses (warm.rs).
    warm: warm::Kept<T>,
}

/// What a soft step did, for the step's report.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoftOutcome {
    pub substeps: usize,
    /// The deepest penetration before and after the step (m).
    pub max_penetration_before: f64,
    pub max_penetration_after: f64,
    /// The fastest closing normal speed before and after the step (m/s, ≥ 0).
    pub max_closing_before: f64,
    pub max_closing_after: f64,
}

impl<T: Real> Default for SoftSolver<T> {
    fn default() -> Self {
        SoftSolver {
            contacts: Vec::new(),
            inverse_inertia: Vec::new(),
            moving: Vec::new(),
            warm: warm::Kept::default(),
        }
    }
}

impl<T: Real> SoftSolver<T> {
    /// One step of `world` under `p`: every body for which `moving(i)` holds
    /// has its velocity and position integrated over the step's substeps with
    /// the contacts solved in between. `trace`, when given, records the
    /// contacts' coefficients and each substep's impulses.
    pub fn step(
        &mut self,
        world: &mut World<T>,
        p: &SimParams<T>,
        moving: impl Fn(usize) -> bool,
        mut trace: Option<&mut SoftTrace>,
    ) -> SoftOutcome {
        let r = &p.resolver;
        let substeps = r.substeps.max(1);
        let h = p.dt / c::<T>(substeps as f64);
        let soft = Softness::new(
            r.soft.contact_hertz,
            r.soft.contact_damping_ratio,
            to_f64(h),
        );
        self.moving.clear();
        self.moving
            .extend((0..world.bodies.len()).map(|i| world.bodies[i].movable && moving(i)));
        self.inverse_inertia.clear();
        self.inverse_inertia
            .extend(world.bodies.iter().zip(&self.moving).map(|(b, &m)| {
                if m {
                    b.state.inverse_inertia_world()
                } else {
                    Matrix3::zeros()
                }
            }));
        self.contacts.clear();
        let slip = c::<T>(r.slip());
        for k in &world.contacts {
            let mut contact =
                SoftContact::prepare(world, k, &self.moving, &self.inverse_inertia, slip);
            self.warm.restore(k, &mut contact);
            self.contacts.push(contact);
        }
        let before = solve::closing_and_depth(&self.contacts, &world.bodies);
        if let Some(t) = trace.as_deref_mut() {
            t.begin(
                (to_f64(p.dt), substeps, to_f64(h)),
                r,
                soft,
                &self.contacts,
                &world.contacts,
            );
        }
        let kept = Kept::over(p.world.linear_damping, p.world.angular_damping, h);
        let push_out = c::<T>(r.soft.push_out_speed);
        let soft_t = [soft.bias_rate, soft.mass_scale, soft.impulse_scale].map(c::<T>);
        for _ in 0..substeps {
            for (body, _) in (world.bodies.iter_mut().zip(&self.moving)).filter(|(_, &m)| m) {
                integrate_velocity_kept(
                    &mut body.state,
                    &p.world.gravity,
                    &Loads::default(),
                    &kept,
                    h,
                );
            }
            let inertia = &self.inverse_inertia;
            solve::warm_start(&mut world.bodies, inertia, &self.contacts);
            solve::solve(
                &mut world.bodies,
                inertia,
                &mut self.contacts,
                Some((soft_t, push_out)),
                h,
            );
            for (body, _) in (world.bodies.iter_mut().zip(&self.moving)).filter(|(_, &m)| m) {
                integrate_position(&mut body.state, h);
            }
            for _ in 0..r.soft.relax_iterations {
                solve::solve(
                    &mut world.bodies,
                    &self.inverse_inertia,
                    &mut self.contacts,
                    None,
                    h,
                );
            }
            if let Some(t) = trace.as_deref_mut() {
                t.substep(&self.contacts, &world.bodies);
            }
        }
        let threshold = c::<T>(r.soft.restitution_threshold);
        solve::restitution(
            &mut world.bodies,
            &self.inverse_inertia,
            &mut self.contacts,
            threshold,
        );
        let after = solve::closing_and_depth(&self.contacts, &world.bodies);
        self.warm.store(&world.contacts, &self.contacts);
        if let Some(t) = trace {
            t.end(&self.contacts);
        }
        SoftOutcome {
            substeps,
            max_penetration_before: before.1,
            max_penetration_after: after.1,
            max_closing_before: before.0,
            max_closing_after: after.0,
        }
    }
}
