//! Every tunable of the physics, one documented struct per level, each field
//! saying what it trades and its default (written rapier-style).
//!
//! - [`ContactParams`]: how ONE contact is resolved (per contact, overridable);
//! - [`StepParams`]: what belongs to a time step (the frame's duration);
//! - [`ResolverParams`]: how a SET of contacts is resolved together;
//! - [`WorldParams`], [`SleepParams`]: the forces and sleep of a simulation;
//! - [`SimParams`]: all of these, for a run in float type `T`;
//! - [`Settings`]: every knob's value as a lesson or a command line gives it
//!   (f64), read and written through the knob table (`knobs`).

use nalgebra::Vector3;

use super::exact::RestitutionLaw;
use super::{c, Real};

/// Restitution is 0 below this closing speed for generated contacts (the
/// reference engine's); the lecture's hand-written contacts default to 0.
pub const GENERATED_VELOCITY_LIMIT: f64 = 0.25;

/// How friction is modelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FrictionModel {
    /// The lecture and reference engine: solve for the impulse that removes all
    /// sliding, then clamp it to the Coulomb cone.
    #[default]
    Millington,
    /// The collisions lectures (Lecture IV Collisions; Pronost's Game
    /// Physics): impulse `j(n + μ_k t)`, t against the sliding direction.
    KineticDirection,
    /// The friction lecture (PSE Friction): remove the planar velocity below
    /// `v_c μ_s`, otherwise scale it by μ_d.
    VelocityScaling,
}

impl FrictionModel {
    pub const ALL: [FrictionModel; 3] = [
        FrictionModel::Millington,
        FrictionModel::KineticDirection,
        FrictionModel::VelocityScaling,
    ];
}

/// How penetration is resolved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ProjectionMethod {
    /// Inverse-mass weighting only: no rotation.
    Linear,
    /// The lecture's nonlinear projection: linear and angular inertia share the move.
    #[default]
    Nonlinear,
}

/// How one contact is resolved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactParams<T: Real> {
    /// Restitution is forced to 0 below this closing speed: trades bounce
    /// fidelity at low speed for resting contacts that do not vibrate
    /// (default: 0; the reference engine uses 0.25).
    pub velocity_limit: T,
    /// Max angular move as a multiple of |r⊥| in projection: trades
    /// believable rotation for robustness against over-rotation
    /// (default: 0.2; `inf` = off).
    pub angular_limit: T,
    /// Share of the penetration resolved in one projection, (0, 1]: trades
    /// speed of separation for stability when many contacts touch one body
    /// (default: 1).
    pub relaxation: T,
    /// Linear or nonlinear projection: trades the lecture's believable
    /// rotation for a cheaper move without rotation (default: nonlinear).
    pub projection: ProjectionMethod,
    /// Integrate the impact exactly under this restitution law beside the
    /// one-shot impulse (the `exact_impact` stage): trades the cost of an
    /// integration for the accuracy reference; applies nothing
    /// (default: none, the stage is skipped).
    pub exact: Option<RestitutionLaw>,
}

impl<T: Real> Default for ContactParams<T> {
    fn default() -> Self {
        ContactParams {
            velocity_limit: T::zero(),
            angular_limit: c(0.2),
            relaxation: T::one(),
            projection: ProjectionMethod::Nonlinear,
            exact: None,
        }
    }
}

/// What belongs to a time step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepParams<T: Real> {
    /// Last frame's duration, for acceleration compensation: the velocity
    /// `a·duration` that one frame of acceleration builds up is not bounced
    /// back (default: 0.01 s).
    pub duration: T,
    /// Add the planar part of `a·duration` to each contact velocity, as the
    /// reference engine does: it integrates positions before it resolves, so
    /// friction must remove next step's build-up too or a box creeps down a
    /// slope. A stepper that resolves between the velocity and the position
    /// update does not need it (default: true).
    pub anticipate_planar_acceleration: bool,
    /// A contact with a gap g > 0 (negative penetration) whose restitution
    /// as applied is 0 removes only the closing velocity beyond g/duration
    /// (a speculative contact); the stepper turns it on (default: false, a
    /// lesson's contacts are resolved as the lecture does).
    pub speculative: bool,
}

impl<T: Real> Default for StepParams<T> {
    fn default() -> Self {
        StepParams {
            duration: c(0.01),
            anticipate_planar_acceleration: true,
            speculative: false,
        }
    }
}

/// Which contact velocity restitution is applied to in the velocity phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RestitutionFrom {
    /// The contact velocity when the contact is taken, as the reference engine does.
    #[default]
    Current,
    /// The contact velocity before the phase began, as Box2D v3 does.
    Initial,
}

/// Which algorithm resolves a set of contacts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Solver {
    /// The lecture's: the deepest penetration (largest desired Δv) first,
    /// one contact at a time, a one-shot impulse per visit.
    #[default]
    DeepestFirst,
    /// Sequential impulses (projected Gauss–Seidel): every contact in turn,
    /// sweep after sweep, with accumulated and clamped impulses.
    SequentialImpulse,
    /// Box2D v3's soft step: substeps, soft contacts (a frequency and a
    /// damping ratio), a relax pass and a restitution pass.
    SoftStep,
    /// Extended position based dynamics (Müller et al. 2020): substeps of
    /// one position iteration each (λ and compliance per contact), then a
    /// velocity pass (dynamic friction, restitution); integrates itself.
    Xpbd,
    /// Simultaneous impact: the velocity phase as one linear
    /// complementarity problem over every contact, solved by Lemke's
    /// method (the position phase is the lecture's projection).
    Lcp,
}

/// The restitution law of the simultaneous (LCP) velocity phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LcpRestitution {
    /// Kinematic: each contact's separating velocity after is at least
    /// −e times its closing velocity before (one LCP).
    #[default]
    Newton,
    /// Kinetic: a compression LCP to zero closing velocity, then each
    /// contact's restitution impulse e times its compression impulse.
    Poisson,
}

/// How a set of contacts is resolved together (the lecture's two phases).
/// Iterations are counted in contact visits for both solvers: one
/// deepest-first iteration visits one contact, one sequential-impulse sweep
/// visits every contact, so equal limits mean equal work.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResolverParams {
    /// Most position-phase iterations (contact visits): trades time for
    /// penetration left (default: `None` = `visits_per_contact` × contacts).
    pub position_iterations: Option<usize>,
    /// Most velocity-phase iterations (contact visits): trades time for
    /// closing velocity left (default: `None` = `visits_per_contact` × contacts).
    pub velocity_iterations: Option<usize>,
    /// Penetrations at or below this are left alone: trades resting jitter
    /// for penetration left (default: 0.01).
    pub position_epsilon: f64,
    /// Desired Δv at or below this is left alone: trades time for closing
    /// velocity left (default: 0.01).
    pub velocity_epsilon: f64,
    /// Sequential impulses: the slip speed at or below which a contact
    /// sticks under μ_s (above it, it slides under μ_d) (default: `None` =
    /// `velocity_epsilon`).
    pub slip_speed: Option<f64>,
    /// Restitution from the current or the initial contact velocity (default:
    /// current). Sequential impulses always take it from the initial velocity.
    pub restitution_from: RestitutionFrom,
    /// Deepest-first (the lecture's) or sequential impulses: trades the
    /// lecture's one-shot impulses, exact for one contact, for accumulated
    /// impulses that settle coupled contacts (default: deepest_first).
    pub solver: Solver,
    /// Sequential impulses only: start from the previous step's accumulated
    /// impulses (matched by body pair and contact point): trades a little
    /// bookkeeping for fewer sweeps on resting contacts (default: false).
    pub warm_start: bool,
    /// The limit of each phase when no explicit count is given, per contact:
    /// trades time for what is left (default: 8, the lecture's 8 × contacts).
    pub visits_per_contact: usize,
    /// Soft step and XPBD: substeps per step: trades time for stiffer,
    /// more accurate contacts (default: 4, Box2D's and rapier's).
    pub substeps: usize,
    /// The soft step's coefficients and passes.
    pub soft: SoftParams,
    /// The simultaneous solver's restitution law (default: newton).
    pub lcp_restitution: LcpRestitution,
}

impl Default for ResolverParams {
    fn default() -> Self {
        ResolverParams {
            position_iterations: None,
            velocity_iterations: None,
            position_epsilon: 0.01,
            velocity_epsilon: 0.01,
            slip_speed: None,
            restitution_from: RestitutionFrom::Current,
            solver: Solver::DeepestFirst,
            warm_start: false,
            visits_per_contact: 8,
            substeps: 4,
            soft: SoftParams::default(),
            lcp_restitution: LcpRestitution::Newton,
        }
    }
}

impl ResolverParams {
    /// The stick/slip threshold of sequential impulses.
    pub fn slip(&self) -> f64 {
        self.slip_speed.unwrap_or(self.velocity_epsilon)
    }

    /// The position iteration limit for `contacts` contacts.
    pub fn position_limit(&self, contacts: usize) -> usize {
        self.position_iterations
            .unwrap_or(self.visits_per_contact.saturating_mul(contacts))
    }

    /// The velocity iteration limit for `contacts` contacts.
    pub fn velocity_limit(&self, contacts: usize) -> usize {
        self.velocity_iterations
            .unwrap_or(self.visits_per_contact.saturating_mul(contacts))
    }
}

/// The forces of a simulated world.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorldParams<T: Real> {
    /// Uniform acceleration of every movable body (default: (0, -9.81, 0) m/s²).
    pub gravity: Vector3<T>,
    /// Fraction of linear velocity kept per second, (0, 1]: trades energy
    /// lost for stability (default: 0.99; 1 = no damping).
    pub linear_damping: T,
    /// Fraction of angular velocity kept per second, (0, 1] (default: 0.99).
    pub angular_damping: T,
}

impl<T: Real> Default for WorldParams<T> {
    fn default() -> Self {
        WorldParams {
            gravity: Vector3::new(T::zero(), c(-9.81), T::zero()),
            linear_damping: c(0.99),
            angular_damping: c(0.99),
        }
    }
}

/// When bodies stop being simulated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleepParams<T: Real> {
    /// Whether bodies may sleep: trades the cost of simulating resting bodies
    /// for the risk of freezing one that should still move (default: true).
    pub enabled: bool,
    /// Motion (recency-weighted `v·v + ω·ω`) below which a body sleeps
    /// (default: 0.3, the reference engine's).
    pub epsilon: T,
    /// Per body, as the lecture; or per island of touching bodies (default: body).
    pub mode: SleepMode,
    /// Island mode: how long every body of an island must have been slow (default: 0.5 s).
    pub island_time: T,
}

impl<T: Real> Default for SleepParams<T> {
    fn default() -> Self {
        SleepParams {
            enabled: true,
            epsilon: c(0.3),
            mode: SleepMode::Body,
            island_time: c(0.5),
        }
    }
}

/// Which contacts a pair of boxes generates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BoxBoxMode {
    /// One point–face or edge–edge contact, as the reference engine: cheap,
    /// but a box resting on a box rocks on one point.
    Single,
    /// The reference face clipped against the incident face, up to 4 points:
    /// costs more, stacks stand (default).
    #[default]
    Manifold,
}

/// Which routine a convex pair runs (`[world] narrow_phase`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NarrowPhase {
    /// The analytic routine where one exists (sphere, box and plane pairs),
    /// GJK/EPA and the clipped manifold for every other convex pair (default).
    #[default]
    Analytic,
    /// GJK/EPA and the clipped manifold for every pair but a half-space's.
    Gjk,
}

/// How the broad phase finds the pairs whose boxes overlap (`[world]
/// broad_phase`). Every method finds the same pairs in the same order: a
/// run is the same state for state under each; only the cost differs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum BroadPhaseMethod {
    /// Sort and sweep on the axis of largest spread (default).
    #[default]
    Sweep,
    /// A uniform grid: each box hashed into every cell it overlaps.
    Grid,
    /// A dynamic bounding-volume tree of fat boxes, queried per body.
    Bvh,
}

/// A mesh's contact normal on an edge or corner shared with another
/// triangle (`[world] internal_edges`): `Corrected` (default) turns a normal
/// that no neighbouring face allows to the face's (no bump at the seam of
/// two coplanar triangles); `Raw` keeps the triangle's own normal, the
/// ghost collision a lesson shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum InternalEdges {
    #[default]
    Corrected,
    Raw,
}

/// Restitution and friction coefficients: of a contact, a body, or
/// `[world]`'s default. One rule wherever they are written: `friction` sets
/// both μ_s and μ_d, and μ_d defaults to μ_s ([`Material::with`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    pub restitution: f64,
    pub static_friction: f64,
    pub dynamic_friction: f64,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            restitution: 0.0,
            static_friction: 0.0,
            dynamic_friction: 0.0,
        }
    }
}

impl Material {
    /// `self` with the coefficients a table writes: `friction` sets both,
    /// `static_friction` μ_s, `dynamic_friction` μ_d; a μ_s given without a
    /// μ_d (or a `friction`) sets μ_d too.
    pub fn with(
        &self,
        restitution: Option<f64>,
        friction: Option<f64>,
        static_friction: Option<f64>,
        dynamic_friction: Option<f64>,
    ) -> Material {
        let mut m = *self;
        if let Some(e) = restitution {
            m.restitution = e;
        }
        if let Some(mu) = friction {
            m.static_friction = mu;
            m.dynamic_friction = mu;
        }
        if let Some(mu) = static_friction {
            m.static_friction = mu;
            if friction.is_none() && dynamic_friction.is_none() {
                m.dynamic_friction = mu;
            }
        }
        if let Some(mu) = dynamic_friction {
            m.dynamic_friction = mu;
        }
        m
    }

    /// The coefficients of a contact between two bodies, as Box2D combines
    /// them: restitution the larger, friction the geometric mean √(μ₁μ₂).
    pub fn combine(&self, other: &Material) -> Material {
        Material {
            restitution: self.restitution.max(other.restitution),
            static_friction: (self.static_friction * other.static_friction).sqrt(),
            dynamic_friction: (self.dynamic_friction * other.dynamic_friction).sqrt(),
        }
    }
}

pub mod ccd_mode;
mod settings;
pub mod soft;
pub use ccd_mode::{Ccd, NormalFrom, Rollback};
pub use settings::{ContactSettings, SceneSettings, Settings, SimParams};
pub use soft::{SoftParams, Softness};

/// How bodies fall asleep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SleepMode {
    /// Each body on its own (the lecture and the reference engine).
    #[default]
    Body,
    /// An island of touching movable bodies sleeps together, once all its
    /// bodies have been slow for `island_time` (Box2D, Bullet, PhysX).
    Island,
}
