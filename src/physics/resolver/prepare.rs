//! Prepare every contact once (the reference engine's `calculateInternals`):
//! basis, arms r, world inverse inertia, contact velocity, desired Δv, and
//! what projection and impulse need that does not change while the phases
//! run, with the single-contact stages' own functions (each body's I⁻¹ is
//! computed once, not once per contact). As in the reference engine, r and I⁻¹ are NOT refreshed after a body
//! moves: both phases use the geometry as prepared.

use nalgebra::{Matrix3, Quaternion, Vector3};

use crate::physics::frame::contact_basis;
use crate::physics::params::RestitutionFrom;
use crate::physics::stages::desired_velocity::{
    acceleration_terms, applied_restitution, contact_velocity, desired_from, desired_toward_bounce,
    relative_acceleration,
};
use crate::physics::stages::projection::{
    projection_inertia_from, total_projection_inertia, ProjectionInertia,
};
use crate::physics::stages::unit_impulse::{
    angular_response, body_unit_response, combine_unit_responses, total_per_unit_impulse,
};
use crate::physics::{BodyId, FrictionModel, Real, World};

/// A movable body as the resolver moves it.
#[derive(Debug, Clone, PartialEq)]
pub struct ResolverBody<T: Real> {
    /// The body in the world (immovable bodies are not resolver bodies).
    pub id: BodyId,
    pub inverse_mass: T,
    /// `R I_b⁻¹ Rᵀ` at prepare.
    pub inverse_inertia_world: Matrix3<T>,
    pub position: Vector3<T>,
    /// Unit quaternion `[w, x, y, z]`.
    pub orientation: Quaternion<T>,
    pub velocity: Vector3<T>,
    pub angular_velocity: Vector3<T>,
}

impl<T: Real> ResolverBody<T> {
    /// The orientation normalised once more, as reports show it.
    pub fn unit_orientation(&self) -> Quaternion<T> {
        self.orientation.normalize()
    }
}

/// The friction part of a contact (only contacts with friction have one).
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionData<T: Real> {
    pub model: FrictionModel,
    pub static_friction: T,
    pub dynamic_friction: T,
    /// The contact-space 3×3 matrix `M` (velocity change per unit impulse).
    pub matrix: Matrix3<T>,
}

/// One contact with the resolver's bookkeeping: what every update reads or
/// writes (`repr(C)` keeps it together, the taken contact's own constants
/// are in [`ContactSetup`], so updates touch fewer cache lines).
#[derive(Debug, Clone, PartialEq)]
#[repr(C)]
pub struct ResolverContact<T: Real> {
    /// The bookkeeping penetration, updated linearly as bodies move.
    pub penetration: T,
    /// Desired Δv along the normal, recomputed when `velocity` changes.
    pub desired: T,
    /// Resolver body index of body 1 and body 2; `None` for the world or an immovable body.
    pub bodies: [Option<usize>; 2],
    pub normal: Vector3<T>,
    /// `r = q - p` of each slot at prepare (zero for an empty slot).
    pub r: [Vector3<T>; 2],
    /// The bookkeeping contact velocity (contact space), updated linearly.
    pub velocity: Vector3<T>,
    /// Columns d, t0, t1.
    pub basis: Matrix3<T>,
    /// `v_s` at prepare (restitution from the initial velocity uses it).
    pub initial_velocity: T,
    /// `(a₁ - a₂)·d Δt`.
    pub velocity_from_acceleration: T,
    pub restitution: T,
    pub velocity_limit: T,
}

/// What only the contact's own resolution reads (its projection and impulse).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSetup<T: Real> {
    pub relaxation: T,
    /// Each slot's share of a projection (depth-independent part).
    pub projection: [Option<ProjectionInertia<T>>; 2],
    pub total_inertia: T,
    /// `Δq̇_t`, velocity change along d per unit impulse.
    pub unit_total: T,
    /// Index into the friction data, for a contact with friction.
    pub friction: Option<usize>,
}

/// Body → contacts, movable bodies only, in compressed rows: the contacts of
/// body `b` are `contacts[offsets[b]..offsets[b + 1]]`, in file order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Adjacency {
    pub offsets: Vec<usize>,
    pub contacts: Vec<usize>,
    /// Scratch for the build (kept so a rebuild allocates nothing).
    fill: Vec<usize>,
}

impl Adjacency {
    pub fn build(bodies: usize, slots: impl Iterator<Item = [Option<usize>; 2]> + Clone) -> Self {
        let mut a = Adjacency::default();
        a.build_into(bodies, slots);
        a
    }

    /// Rebuilds in place (no allocation when the storage is big enough).
    pub fn build_into(
        &mut self,
        bodies: usize,
        slots: impl Iterator<Item = [Option<usize>; 2]> + Clone,
    ) {
        self.offsets.clear();
        self.offsets.resize(bodies + 1, 0);
        for s in slots.clone() {
            for b in s.into_iter().flatten() {
                self.offsets[b + 1] += 1;
            }
        }
        for b in 0..bodies {
            self.offsets[b + 1] += self.offsets[b];
        }
        self.contacts.clear();
        self.contacts.resize(self.offsets[bodies], 0);
        self.fill.clear();
        self.fill.extend_from_slice(&self.offsets[..bodies]);
        for (k, s) in slots.enumerate() {
            for b in s.into_iter().flatten() {
                self.contacts[self.fill[b]] = k;
                self.fill[b] += 1;
            }
        }
    }

    /// The contacts of resolver body `b`.
    pub fn of(&self, b: usize) -> &[usize] {
        &self.contacts[self.offsets[b]..self.offsets[b + 1]]
    }
}

/// Desired Δv of a contact from its bookkeeping velocity (velocity limit included).
pub fn desired_of<T: Real>(c: &ResolverContact<T>, from: RestitutionFrom) -> T {
    let v = c.velocity.x;
    match from {
        RestitutionFrom::Current => {
            let (e, _) = applied_restitution(v, c.restitution, c.velocity_limit);
            desired_from(v, e, c.velocity_from_acceleration)
        }
        RestitutionFrom::Initial => {
            let v0 = c.initial_velocity;
            let (e, _) = applied_restitution(v0, c.restitution, c.velocity_limit);
            desired_toward_bounce(v, v0, e, c.velocity_from_acceleration)
        }
    }
}

/// A world's bodies, contacts, friction data and adjacency, prepared.
#[derive(Debug, Clone, PartialEq)]
pub struct Prepared<T: Real> {
    pub bodies: Vec<ResolverBody<T>>,
    pub contacts: Vec<ResolverContact<T>>,
    pub setups: Vec<ContactSetup<T>>,
    pub friction: Vec<FrictionData<T>>,
    pub adjacency: Adjacency,
    /// World body → resolver body (scratch kept for the next prepare).
    pub index: Vec<Option<usize>>,
}

/// Prepares every movable body and every contact of `world`.
pub fn prepare<T: Real>(world: &World<T>, from: RestitutionFrom) -> Prepared<T> {
    let mut prepared = Prepared {
        bodies: Vec::new(),
        contacts: Vec::new(),
        setups: Vec::new(),
        friction: Vec::new(),
        adjacency: Adjacency::default(),
        index: Vec::new(),
    };
    prepare_into(world, from, &mut prepared);
    prepared
}

/// Prepares `world` into `out`, reusing its storage: nothing is allocated
/// when it already holds a world this size (as an engine resolving every
/// frame would use it).
pub fn prepare_into<T: Real>(world: &World<T>, from: RestitutionFrom, out: &mut Prepared<T>) {
    let Prepared {
        bodies,
        contacts,
        setups,
        friction,
        adjacency,
        index,
    } = out;
    index.clear();
    index.resize(world.bodies.len(), None);
    bodies.clear();
    for (i, body) in world.bodies.iter().enumerate() {
        if let Some(b) = body.dynamic() {
            index[i] = Some(bodies.len());
            bodies.push(ResolverBody {
                id: BodyId(i),
                inverse_mass: b.inverse_mass,
                inverse_inertia_world: b.inverse_inertia_world(),
                position: b.position,
                orientation: b.orientation,
                velocity: b.velocity,
                angular_velocity: b.angular_velocity,
            });
        }
    }
    friction.clear();
    setups.clear();
    contacts.clear();
    contacts.extend(world.contacts.iter().map(|contact| {
        let input = &contact.input;
        let slots = contact.slots().map(|id| index[id?.0]);
        let bodies = &*bodies;
        let body = |i: usize| slots[i].map(|b| (&bodies[b], &world.bodies[bodies[b].id.0].state));
        // Contact frame (stage 1): basis and arms.
        let (basis, _) = contact_basis(&input.normal);
        let d = input.normal;
        let r = [0, 1].map(|i| body(i).map(|(b, _)| input.point - b.position));
        // Velocity change per unit impulse (stage 2), from the bodies'
        // prepared I⁻¹; the projection's angular inertia is the same number.
        let responses = [0, 1].map(|i| {
            let (b, _) = body(i)?;
            Some(angular_response(&b.inverse_inertia_world, &r[i]?, &d))
        });
        let projection = [0, 1].map(|i| {
            let (b, _) = body(i)?;
            Some(projection_inertia_from(
                b.inverse_mass,
                responses[i].as_ref()?,
                &r[i]?,
                &d,
                &input.settings,
            ))
        });
        let (_, unit_total) = total_per_unit_impulse(
            &[0, 1].map(|i| Some((body(i)?.0.inverse_mass, responses[i]?.angular))),
        );
        // Only a contact with friction builds the 3×3 matrix.
        let matrix = input.has_friction().then(|| {
            let bodies = [0, 1].map(|i| {
                let (b, _) = body(i)?;
                Some(body_unit_response(
                    b.inverse_mass,
                    b.inverse_inertia_world,
                    r[i]?,
                    &d,
                    true,
                ))
            });
            combine_unit_responses(bodies, &basis, true).matrix
        });
        // Contact velocity and the acceleration terms (stage 3).
        let point_velocity = [0, 1].map(|i| {
            let (_, state) = body(i)?;
            Some(state.point_velocity(&r[i]?))
        });
        let acceleration =
            relative_acceleration([0, 1].map(|i| body(i).map(|(_, s)| s.acceleration)));
        let duration = contact.duration.unwrap_or(world.step.duration);
        let (velocity_from_acceleration, mut planar) =
            acceleration_terms(&acceleration, &basis, duration);
        if !world.step.anticipate_planar_acceleration {
            planar = Vector3::zeros();
        }
        let (_, velocity) = contact_velocity(&point_velocity, &basis, &planar);
        let friction_index = matrix.flatten().map(|matrix| {
            friction.push(FrictionData {
                model: input.friction_model,
                static_friction: input.static_friction,
                dynamic_friction: input.dynamic_friction,
                matrix,
            });
            friction.len() - 1
        });
        let mut c = ResolverContact {
            penetration: input.penetration,
            desired: T::zero(),
            bodies: slots,
            normal: d,
            r: r.map(|r| r.unwrap_or_else(Vector3::zeros)),
            velocity,
            basis,
            initial_velocity: velocity.x,
            velocity_from_acceleration,
            restitution: input.restitution,
            velocity_limit: input.settings.velocity_limit,
        };
        c.desired = desired_of(&c, from);
        setups.push(ContactSetup {
            relaxation: input.settings.relaxation,
            total_inertia: total_projection_inertia(&projection),
            projection,
            unit_total,
            friction: friction_index,
        });
        c
    }));
    adjacency.build_into(bodies.len(), contacts.iter().map(|c| c.bodies));
}
