//! Pure maths: no I/O, no text. Everything is generic over the float type so
//! that f32 and f64 runs can be compared.
//!
//! - [`body`], [`shape`], [`world`]: bodies by id, their shapes, the world of a scene;
//! - [`params`]: the typed parameters, one struct per level (the knob table
//!   that names them is `crate::knobs`, above physics);
//! - [`contact`]: ONE contact — frame, problem view, stages, solve, checks
//!   and the causes of their verdicts;
//! - [`scale`]: scale-invariant norms and inverse (power-of-two scaling);
//! - beside it, for sets of contacts over time: `resolver/` (a scene's contacts
//!   resolved together), `collide/` (contact generation), `step/` (time
//!   stepping, micro-collisions, sleep) and `exact/` (impact integration).

pub mod body;
pub mod collide;
pub mod contact;
pub mod detect;
pub mod exact;
pub mod hull;
pub mod hull_faces;
pub mod lcp;
pub mod mesh;
pub mod mesh_mass;
pub mod params;
pub mod pose;
pub mod resolver;
pub mod scale;
pub mod shape;
pub mod step;
pub mod world;

pub use body::RigidBody;
pub use contact::{causes, checks, frame, problem, solve, stages};
pub use contact::{ContactInput, Problem, Solution, StageId};
pub use params::{
    ContactParams, ContactSettings, FrictionModel, LcpRestitution, ProjectionMethod,
    ResolverParams, RestitutionFrom, SceneSettings, Settings, SimParams, SleepParams, Solver,
    StepParams, WorldParams,
};
pub use shape::Shape;
pub use world::{Body, BodyId, Contact, World};

use nalgebra::RealField;

/// The float types the stage maths runs on (f32 and f64).
pub trait Real: RealField + Copy {}
impl<T: RealField + Copy> Real for T {}

/// Converts an f64 constant into the working float type.
pub fn c<T: Real>(x: f64) -> T {
    nalgebra::convert(x)
}

/// Converts a working float back to f64 (for the trace and comparisons).
pub fn to_f64<T: Real>(x: T) -> f64 {
    nalgebra::try_convert(x).unwrap_or(f64::NAN)
}
