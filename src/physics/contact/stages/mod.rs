//! One module per resolution stage, each a pure function returning a record,
//! and beside it its `_into` form writing the record into a place the
//! caller holds (what `solve_stages` calls: no record is built on the stack
//! and moved). The record-returning form calls the `_into` one, so each
//! stage's maths is written once. The order here is the order of the
//! lecture (and of the trace).

pub mod apply_impulse;
pub mod contact_frame;
pub mod desired_velocity;
pub mod friction;
pub mod impulse;
pub mod orientation;
pub mod projection;
pub mod unit_impulse;

pub use apply_impulse::{
    apply_impulse, apply_impulse_into, apply_impulse_with, AppliedImpulse, BodyVelocityChange,
};
pub use contact_frame::{contact_frame, contact_frame_into, ContactFrame};
pub use desired_velocity::{desired_delta_velocity, desired_delta_velocity_into, DesiredVelocity};
pub use friction::{friction_clamp, friction_clamp_factored_into, FrictionClamp, FrictionRegime};
pub use impulse::{
    condition_number, impulse, impulse_factored_into, impulse_with, FactoredMatrix, Impulse,
    MatrixSolve,
};
pub use orientation::{
    orientation_update, orientation_update_into, BodyOrientation, OrientationUpdate, Turn,
};
pub use projection::{
    nonlinear_projection, nonlinear_projection_into, nonlinear_projection_with, BodyProjection,
    Projection,
};
pub use unit_impulse::{
    unit_impulse, unit_impulse_into, unit_impulse_with, BodyUnitResponse, UnitImpulse,
};
