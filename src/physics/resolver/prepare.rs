//! Prepare every contact once (the reference engine's `calculateInternals`):
//! basis, arms r, world inverse inertia, contact velocity, desired Δv, and
//! what projection and impulse need that does not change while the phases
//! run, with the single-contact stages' own functions (each body's I⁻¹ is
//! computed once, not once per contact). As in the reference engine, r and I⁻¹ are NOT refreshed after a body
//! moves: both phases use the geometry as prepared.

use nalgebra::{Matrix3, Quaternion, Vector3};

use crate::physics::frame::{contact_basis, skew};
use crate::physics::params::RestitutionFrom;
use crate::physics::stages::desired_velocity::{
    acceleration_terms, applied_restitution, contact_velocity, desired_from, desired_toward_bounce,
    relative_acceleration,
};
use crate::physics::stages::impulse::FactoredMatrix;
use crate::physics::stages::projection::{
    projection_inertia_from, total_projection_inertia, ProjectionInertia,
};
use crate::physics::stages::unit_impulse::{
    angular_matrix, angular_response, contact_matrix, total_per_unit_impulse,
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
    /// The contact-space 3×3 matrix `M` (velocity change per unit impulse),
    /// factored once here for every visit of the velocity phase.
    pub matrix: FactoredMatrix<T>,
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
    /// A speculative contact's `g/Δt`: the closing speed its gap g > 0
    /// absorbs in the step (zero when touching, or when the step does not
    /// ask for it: `StepParams::speculative`).
    pub gap_speed: T,
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
    /// Slip speed before this step's accelerations, `|v_t - a_t Δt|` (the
    /// tangential contact velocity the bodies give, less what the relative
    /// acceleration built up over the step); zero without friction.
    pub slip: T,
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
        // Counts shifted by one, then their running sum: row starts.
        let counts = &mut self.offsets[1..];
        for s in slots.clone() {
            for b in s.into_iter().flatten() {
                counts[b] += 1;
            }
        }
        let mut sum = 0;
        for o in counts.iter_mut() {
            sum += *o;
            *o = sum;
        }
        self.contacts.clear();
        self.contacts.resize(sum, 0);
        self.fill.clear();
        self.fill.extend_from_slice(&self.offsets[..bodies]);
        let (fill, contacts) = (&mut self.fill[..], &mut self.contacts[..]);
        for (k, s) in slots.enumerate() {
            for b in s.into_iter().flatten() {
                contacts[fill[b]] = k;
                fill[b] += 1;
            }
        }
    }

    /// The contacts of resolver body `b`.
    pub fn of(&self, b: usize) -> &[usize] {
        &self.contacts[self.offsets[b]..self.offsets[b + 1]]
    }
}

/// Desired Δv of a contact from its bookkeeping velocity (velocity limit
/// included). A speculative contact that does not bounce (restitution as
/// applied 0) wants `Δv = -v_s - g/Δt`: only the closing velocity its gap
/// cannot absorb (Box2D's speculative contact; nothing when it cannot close the gap).
pub fn desired_of<T: Real>(c: &ResolverContact<T>, from: RestitutionFrom) -> T {
    let v = c.velocity.x;
    let (desired, e) = match from {
        RestitutionFrom::Current => {
            let (e, _) = applied_restitution(v, c.restitution, c.velocity_limit);
            (desired_from(v, e, c.velocity_from_acceleration), e)
        }
        RestitutionFrom::Initial => {
            let v0 = c.initial_velocity;
            let (e, _) = applied_restitution(v0, c.restitution, c.velocity_limit);
            (
                desired_toward_bounce(v, v0, e, c.velocity_from_acceleration),
                e,
            )
        }
    };
    if c.gap_speed > T::zero() && e == T::zero() {
        desired - c.gap_speed
    } else {
        desired
    }
}

/// The slip speed (the tangential part of `Cᵀ(q̇₁ - q̇₂)` less the planar
/// acceleration term; zero without friction) and the contact's bookkeeping
/// velocity (`Cᵀ(q̇₁ - q̇₂)` with the planar term added where it is
/// anticipated). Both prepares call it: the same operations on the same bits.
#[inline]
pub(crate) fn slip_and_velocity<T: Real>(
    bodies_velocity: &Vector3<T>,
    planar: Vector3<T>,
    with_friction: bool,
    anticipate_planar: bool,
) -> (T, Vector3<T>) {
    let slip = if with_friction {
        let (y, z) = (bodies_velocity.y - planar.y, bodies_velocity.z - planar.z);
        (y * y + z * z).sqrt()
    } else {
        T::zero()
    };
    let velocity = if anticipate_planar && planar != Vector3::zeros() {
        bodies_velocity + planar
    } else {
        *bodies_velocity
    };
    (slip, velocity)
}

/// What both lean prepares work out of a contact's velocities: `v_acc`,
/// the slip and the bookkeeping velocity ([`acceleration_terms`],
/// [`slip_and_velocity`]) from its bodies' accelerations and `q̇₁ - q̇₂`
/// (`point_velocity`, world), in the contact's `basis`; `duration` is the
/// contact's own, if it has one.
#[inline(always)]
pub(crate) fn lean_velocity_terms<T: Real>(
    world: &World<T>,
    duration: Option<T>,
    accelerations: [Option<Vector3<T>>; 2],
    basis: &Matrix3<T>,
    point_velocity: &Vector3<T>,
    with_friction: bool,
) -> (T, T, Vector3<T>) {
    let acceleration = relative_acceleration(accelerations);
    let duration = duration.unwrap_or(world.step.duration);
    let (velocity_from_acceleration, planar) = acceleration_terms(&acceleration, basis, duration);
    // `Cᵀ(q̇₁ - q̇₂)`: the slip reads it as it is, the bookkeeping velocity
    // with the planar term added.
    let bodies_velocity = basis.transpose() * point_velocity;
    let (slip, velocity) = slip_and_velocity(
        &bodies_velocity,
        planar,
        with_friction,
        world.step.anticipate_planar_acceleration,
    );
    (velocity_from_acceleration, slip, velocity)
}

/// `g/Δt` of a contact with a gap `g = -penetration > 0` in a step that
/// asks for speculative contacts, else zero.
pub(crate) fn gap_speed<T: Real>(world: &World<T>, penetration: T) -> T {
    let dt = world.step.duration;
    if world.step.speculative && penetration < T::zero() && dt > T::zero() {
        -penetration / dt
    } else {
        T::zero()
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
    prepare_into(world, from, false, &mut prepared);
    prepared
}

/// The movable bodies of `world` into `bodies` (each body's world inverse
/// inertia `R I_b⁻¹ Rᵀ` once, shared by all its contacts) and the world body
/// → resolver body map into `index`.
pub fn prepare_bodies<T: Real>(
    world: &World<T>,
    bodies: &mut Vec<ResolverBody<T>>,
    index: &mut Vec<Option<usize>>,
) {
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
}

/// Prepares `world` into `out`, reusing its storage: nothing is allocated
/// when it already holds a world this size (as an engine resolving every
/// frame would use it).
///
/// `inverse_only` (sequential impulses): the friction matrices are left
/// zero here and built, with `M⁻¹` only ([`FactoredMatrix::for_inverse`]),
/// from the contacts' Jacobian rows by `sequential::rows::build`; otherwise
/// they are factored for solving with a condition number (what the
/// deepest-first order reports).
pub fn prepare_into<T: Real>(
    world: &World<T>,
    from: RestitutionFrom,
    inverse_only: bool,
    out: &mut Prepared<T>,
) {
    let Prepared {
        bodies,
        contacts,
        setups,
        friction,
        adjacency,
        index,
    } = out;
    prepare_bodies(world, bodies, index);
    friction.clear();
    setups.clear();
    contacts.clear();
    contacts.extend(world.contacts.iter().map(|contact| {
        let input = &contact.input;
        let slots = contact.slots().map(|id| index[id?.0]);
        // Contact frame (stage 1): basis and arms.
        let (basis, _) = contact_basis(&input.normal);
        let d = input.normal;
        let with_friction = input.has_friction();
        let mut r = [None; 2];
        let mut projection = [None, None];
        let mut unit = [None; 2];
        let mut point_velocity = [None; 2];
        let mut acceleration = [None; 2];
        // Σ −[r]× I⁻¹ [r]× over the bodies (only a contact with friction needs it).
        let mut angular_world = Matrix3::zeros();
        for (i, slot) in slots.iter().enumerate() {
            let Some(b) = *slot else { continue };
            let body = &bodies[b];
            let state = &world.bodies[body.id.0].state;
            let arm = input.point - body.position;
            // Velocity change per unit impulse (stage 2), from the body's
            // prepared I⁻¹; the projection's angular inertia is the same number.
            let response = angular_response(&body.inverse_inertia_world, &arm, &d);
            projection[i] = Some(projection_inertia_from(
                body.inverse_mass,
                &response,
                &arm,
                &d,
                &input.settings,
            ));
            unit[i] = Some((body.inverse_mass, response.angular));
            if with_friction && !inverse_only {
                angular_world += angular_matrix(&skew(&arm), &body.inverse_inertia_world);
            }
            // Contact velocity and the acceleration terms (stage 3).
            point_velocity[i] = Some(state.point_velocity(&arm));
            acceleration[i] = Some(state.acceleration);
            r[i] = Some(arm);
        }
        let (linear, unit_total) = total_per_unit_impulse(&unit);
        // Sequential impulses build `M` from the contact's Jacobian rows
        // instead (`sequential::rows`, `M = Σ A_iᵀ I_i⁻¹ A_i + Σ m⁻¹ 𝟙`).
        let matrix = with_friction.then(|| {
            if inverse_only {
                Matrix3::zeros()
            } else {
                contact_matrix(&angular_world, &basis, linear)
            }
        });
        let acceleration = relative_acceleration(acceleration);
        let duration = contact.duration.unwrap_or(world.step.duration);
        let (velocity_from_acceleration, planar) =
            acceleration_terms(&acceleration, &basis, duration);
        // `Cᵀ(q̇₁ - q̇₂)` once: the slip reads it as it is, the bookkeeping
        // velocity with the planar term added (what `contact_velocity` adds).
        let (_, bodies_velocity) = contact_velocity(&point_velocity, &basis, &Vector3::zeros());
        let (slip, velocity) = slip_and_velocity(
            &bodies_velocity,
            planar,
            with_friction,
            world.step.anticipate_planar_acceleration,
        );
        let friction_index = matrix.map(|matrix| {
            friction.push(FrictionData {
                model: input.friction_model,
                static_friction: input.static_friction,
                dynamic_friction: input.dynamic_friction,
                matrix: if inverse_only {
                    FactoredMatrix::for_inverse(matrix)
                } else {
                    FactoredMatrix::new(matrix)
                },
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
            gap_speed: gap_speed(world, input.penetration),
        };
        c.desired = desired_of(&c, from);
        setups.push(ContactSetup {
            relaxation: input.settings.relaxation,
            total_inertia: total_projection_inertia(&projection),
            projection,
            unit_total,
            friction: friction_index,
            slip,
        });
        c
    }));
    adjacency.build_into(bodies.len(), contacts.iter().map(|c| c.bodies));
}
