//! One module per resolution stage, each a pure function returning a record.
//! The order here is the order of the lecture (and of the trace).

pub mod apply_impulse;
pub mod contact_frame;
pub mod desired_velocity;
pub mod friction;
pub mod impulse;
pub mod orientation;
pub mod projection;
pub mod unit_impulse;

pub use apply_impulse::{apply_impulse, apply_impulse_with, AppliedImpulse, BodyVelocityChange};
pub use contact_frame::{contact_frame, ContactFrame};
pub use desired_velocity::{desired_delta_velocity, DesiredVelocity};
pub use friction::{friction_clamp, friction_clamp_factored, FrictionClamp, FrictionRegime};
pub use impulse::{
    condition_number, impulse, impulse_factored, impulse_with, FactoredMatrix, Impulse, MatrixSolve,
};
pub use orientation::{orientation_update, BodyOrientation, OrientationUpdate, Turn};
pub use projection::{nonlinear_projection, nonlinear_projection_with, BodyProjection, Projection};
pub use unit_impulse::{unit_impulse, unit_impulse_with, BodyUnitResponse, UnitImpulse};
