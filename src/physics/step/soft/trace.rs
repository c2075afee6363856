//! What a traced soft step records: the step's coefficients (from f, ζ and
//! h), each contact's constraint and its normal impulse after every
//! substep, and the impulses the step ends with.

use super::prepare::SoftContact;
use crate::physics::params::{ResolverParams, Softness};
use crate::physics::{to_f64, Body, Real};

/// One contact of a traced soft step.
#[derive(Debug, Clone, PartialEq)]
pub struct TracedContact {
    /// Body indices (body 2 `None`: the world).
    pub body1: usize,
    pub body2: Option<usize>,
    pub penetration: f64,
    /// Normal velocity before the solve (negative when closing, m/s).
    pub relative_velocity: f64,
    pub normal_mass: f64,
    /// The soft coefficients this contact is solved with.
    pub bias_rate: f64,
    pub mass_scale: f64,
    pub impulse_scale: f64,
    pub friction: f64,
    pub restitution: f64,
    /// The normal impulse warm starting began with (N·s).
    pub warm_impulse: f64,
    /// The accumulated normal impulse after each substep (N·s).
    pub substep_impulses: Vec<f64>,
    /// The separation after each substep (m).
    pub substep_separations: Vec<f64>,
    /// After the restitution pass.
    pub normal_impulse: f64,
    pub tangent_impulse: [f64; 2],
}

/// A traced soft step.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SoftTrace {
    pub dt: f64,
    pub substeps: usize,
    /// h = Δt / substeps (s).
    pub h: f64,
    pub contact_hertz: f64,
    pub contact_damping_ratio: f64,
    pub push_out_speed: f64,
    pub relax_iterations: usize,
    pub restitution_threshold: f64,
    pub contacts: Vec<TracedContact>,
}

impl SoftTrace {
    pub(super) fn begin<T: Real>(
        &mut self,
        (dt, substeps, h): (f64, usize, f64),
        r: &ResolverParams,
        soft: Softness,
        contacts: &[SoftContact<T>],
        world: &[crate::physics::Contact<T>],
    ) {
        *self = SoftTrace {
            dt,
            substeps,
            h,
            contact_hertz: r.soft.contact_hertz,
            contact_damping_ratio: r.soft.contact_damping_ratio,
            push_out_speed: r.soft.push_out_speed,
            relax_iterations: r.soft.relax_iterations,
            restitution_threshold: r.soft.restitution_threshold,
            contacts: (contacts.iter().zip(world))
                .map(|(k, w)| TracedContact {
                    body1: w.body1.0,
                    body2: w.body2.map(|b| b.0),
                    penetration: -to_f64(k.separation),
                    relative_velocity: to_f64(k.relative_velocity),
                    normal_mass: to_f64(k.normal_mass),
                    bias_rate: soft.bias_rate,
                    mass_scale: soft.mass_scale,
                    impulse_scale: soft.impulse_scale,
                    friction: to_f64(k.friction),
                    restitution: to_f64(k.restitution),
                    warm_impulse: to_f64(k.normal_impulse),
                    substep_impulses: Vec::with_capacity(substeps),
                    substep_separations: Vec::with_capacity(substeps),
                    normal_impulse: 0.0,
                    tangent_impulse: [0.0; 2],
                })
                .collect(),
        };
    }

    pub(super) fn substep<T: Real>(&mut self, contacts: &[SoftContact<T>], bodies: &[Body<T>]) {
        for (t, k) in self.contacts.iter_mut().zip(contacts) {
            t.substep_impulses.push(to_f64(k.normal_impulse));
            t.substep_separations.push(to_f64(k.separation_now(bodies)));
        }
    }

    pub(super) fn end<T: Real>(&mut self, contacts: &[SoftContact<T>]) {
        for (t, k) in self.contacts.iter_mut().zip(contacts) {
            t.normal_impulse = to_f64(k.normal_impulse);
            t.tangent_impulse = k.tangent_impulse.map(to_f64);
        }
    }
}
