//! The knob values of a run: [`SimParams`] (everything a simulation needs
//! beyond its bodies, in float type `T`) and [`Settings`] (every knob's
//! value as a lesson or a command line gives it, in f64, per level:
//! [`ContactSettings`], [`ResolverParams`], [`SceneSettings`]).

use super::ccd_mode::{Ccd, NormalFrom, Rollback};
use super::{
    BoxBoxMode, BroadPhaseMethod, ContactParams, FrictionModel, InternalEdges, Material,
    NarrowPhase, ProjectionMethod, ResolverParams, SleepParams, StepParams, WorldParams,
    GENERATED_VELOCITY_LIMIT,
};
use crate::physics::exact::RestitutionLaw;
use crate::physics::{c, Real};

/// Everything a simulation needs beyond its bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimParams<T: Real> {
    /// The time step (default: 1/60 s).
    pub dt: T,
    pub world: WorldParams<T>,
    pub sleep: SleepParams<T>,
    pub resolver: ResolverParams,
    /// Parameters of every generated contact (velocity limit, angular limit, …).
    pub contact: ContactParams<T>,
    /// Acceleration compensation (the lecture's micro-collisions): the
    /// velocity one step of acceleration builds up is not bounced back
    /// (default: on). Off, a resting box vibrates.
    pub acceleration_compensation: bool,
    /// How a pair of boxes touches (default: manifold).
    pub box_box: BoxBoxMode,
    /// Analytic routines or GJK/EPA for every convex pair (default: analytic).
    pub narrow_phase: NarrowPhase,
    pub friction_model: FrictionModel,
    /// Contacts are generated for gaps up to this distance (m), with a
    /// negative penetration: a resting body whose contact the position phase
    /// just resolved keeps it, instead of losing it for a step and falling
    /// freely (default: 0.005).
    pub contact_margin: T,
    /// A contact in the margin's gap (g > 0, not bouncing) removes only the
    /// closing velocity beyond g/Δt, as a speculative contact does: the body
    /// falls through the gap instead of stopping on it (default: off, gap
    /// contacts are resolved as touching; the deepest-first solver only).
    pub speculative: bool,
    /// Continuous detection in the step (default: none).
    pub ccd: Ccd,
    /// Projection or rolling back time for interpenetrating pairs (default: projection).
    pub rollback: Rollback,
    /// A penetrating convex pair's normal: now, or from the previous frame (default: current).
    pub normal_from: NormalFrom,
    /// How the broad phase finds its pairs (default: sweep); the same pairs whichever.
    pub broad_phase: BroadPhaseMethod,
    /// A mesh's normals on internal edges: corrected or raw (default: corrected).
    pub internal_edges: InternalEdges,
}

impl<T: Real> Default for SimParams<T> {
    fn default() -> Self {
        Settings::scene_default().sim_params()
    }
}

/// A contact's knobs as a lesson gives them (`[settings]`, a contact's
/// `settings`): its [`ContactParams`], the last frame's duration and the
/// friction model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSettings {
    pub velocity_limit: f64,
    pub angular_limit: f64,
    pub relaxation: f64,
    pub duration: f64,
    pub projection: ProjectionMethod,
    /// The restitution law of the `exact_impact` stage (default: none).
    pub exact: Option<RestitutionLaw>,
    pub friction_model: FrictionModel,
}

impl Default for ContactSettings {
    fn default() -> Self {
        let contact = ContactParams::<f64>::default();
        ContactSettings {
            velocity_limit: contact.velocity_limit,
            angular_limit: contact.angular_limit,
            relaxation: contact.relaxation,
            duration: StepParams::<f64>::default().duration,
            projection: contact.projection,
            exact: contact.exact,
            friction_model: FrictionModel::default(),
        }
    }
}

impl ContactSettings {
    /// The settings a contact's parameters, its frame's duration and its
    /// friction model stand for.
    pub fn of_contact(
        p: &ContactParams<f64>,
        duration: f64,
        friction_model: FrictionModel,
    ) -> Self {
        ContactSettings {
            velocity_limit: p.velocity_limit,
            angular_limit: p.angular_limit,
            relaxation: p.relaxation,
            duration,
            projection: p.projection,
            exact: p.exact,
            friction_model,
        }
    }

    /// The contact's share of the settings, in float type `T`.
    pub fn contact_params<T: Real>(&self) -> ContactParams<T> {
        ContactParams {
            velocity_limit: c(self.velocity_limit),
            angular_limit: c(self.angular_limit),
            relaxation: c(self.relaxation),
            projection: self.projection,
            exact: self.exact,
        }
    }
}

/// What a run needs beyond its bodies and contacts' settings: forces, the
/// step, sleep, contact generation, and the coefficients of generated
/// contacts (`[world]`, `[step]`, `[sleep]`, the bodies' own).
#[derive(Debug, Clone, PartialEq)]
pub struct SceneSettings {
    pub world: WorldParams<f64>,
    pub box_box: BoxBoxMode,
    pub narrow_phase: NarrowPhase,
    /// `[world]`'s coefficients, the default of every body.
    pub material: Material,
    /// Each body's coefficients (the same indices as the lesson's bodies).
    pub materials: Vec<Material>,
    /// The lecture's micro-collisions: one step of acceleration is not bounced back.
    pub acceleration_compensation: bool,
    /// Gap below which contacts are generated (m).
    pub contact_margin: f64,
    /// Gap contacts remove only the closing velocity beyond gap/Δt.
    pub speculative: bool,
    pub dt: f64,
    pub steps: u64,
    pub sleep: SleepParams<f64>,
    pub ccd: Ccd,
    pub rollback: Rollback,
    pub normal_from: NormalFrom,
    pub broad_phase: BroadPhaseMethod,
    pub internal_edges: InternalEdges,
}

impl Default for SceneSettings {
    fn default() -> Self {
        SceneSettings {
            world: WorldParams::default(),
            box_box: BoxBoxMode::default(),
            narrow_phase: NarrowPhase::default(),
            material: Material::default(),
            materials: Vec::new(),
            acceleration_compensation: true,
            contact_margin: 0.005,
            speculative: false,
            dt: 1.0 / 60.0,
            steps: 600,
            sleep: SleepParams::default(),
            ccd: Ccd::None,
            rollback: Rollback::Projection,
            normal_from: NormalFrom::Current,
            broad_phase: BroadPhaseMethod::Sweep,
            internal_edges: InternalEdges::Corrected,
        }
    }
}

/// Every knob's value (see `knobs`): a contact's, the resolver's
/// and a run's.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Settings {
    pub contact: ContactSettings,
    pub resolver: ResolverParams,
    pub scene: SceneSettings,
}

impl Settings {
    /// The defaults of a scene: generated contacts do not bounce below
    /// [`GENERATED_VELOCITY_LIMIT`].
    pub fn scene_default() -> Self {
        let mut s = Settings::default();
        s.contact.velocity_limit = GENERATED_VELOCITY_LIMIT;
        s
    }

    /// The knobs a run's parameters hold (a contact's duration, the steps
    /// and the coefficients are not among them: defaults).
    pub fn of_run(p: &SimParams<f64>) -> Self {
        Settings {
            contact: ContactSettings {
                velocity_limit: p.contact.velocity_limit,
                angular_limit: p.contact.angular_limit,
                relaxation: p.contact.relaxation,
                duration: p.dt,
                projection: p.contact.projection,
                exact: p.contact.exact,
                friction_model: p.friction_model,
            },
            resolver: p.resolver,
            scene: SceneSettings {
                world: p.world,
                box_box: p.box_box,
                narrow_phase: p.narrow_phase,
                acceleration_compensation: p.acceleration_compensation,
                contact_margin: p.contact_margin,
                speculative: p.speculative,
                dt: p.dt,
                sleep: p.sleep,
                ccd: p.ccd,
                rollback: p.rollback,
                normal_from: p.normal_from,
                broad_phase: p.broad_phase,
                internal_edges: p.internal_edges,
                ..SceneSettings::default()
            },
        }
    }

    /// The parameters of a run, in float type `T`.
    pub fn sim_params<T: Real>(&self) -> SimParams<T> {
        let scene = &self.scene;
        SimParams {
            dt: c(scene.dt),
            world: WorldParams {
                gravity: scene.world.gravity.map(c),
                linear_damping: c(scene.world.linear_damping),
                angular_damping: c(scene.world.angular_damping),
            },
            sleep: SleepParams {
                enabled: scene.sleep.enabled,
                epsilon: c(scene.sleep.epsilon),
                mode: scene.sleep.mode,
                island_time: c(scene.sleep.island_time),
            },
            resolver: self.resolver,
            contact: self.contact.contact_params(),
            acceleration_compensation: scene.acceleration_compensation,
            box_box: scene.box_box,
            narrow_phase: scene.narrow_phase,
            friction_model: self.contact.friction_model,
            contact_margin: c(scene.contact_margin),
            speculative: scene.speculative,
            ccd: scene.ccd,
            rollback: scene.rollback,
            normal_from: scene.normal_from,
            broad_phase: scene.broad_phase,
            internal_edges: scene.internal_edges,
        }
    }
}
