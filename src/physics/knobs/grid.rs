//! The study's default grid: the values it tries for each knob, one at a
//! time around a scene's own configuration (the knob table's `grid` field
//! names one of these), and what a scene must have for a knob to be tried
//! ([`Needs`]). The knob table itself stays in `knobs/mod.rs`; a knob with
//! no default grid values says `grid: &[]` there.

/// What a scene must have for a knob to matter in it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Needs {
    Always,
    /// A friction coefficient above 0.
    Friction,
    /// Two boxes or more.
    BoxPairs,
    /// Bodies that can end deep in one another: a mass ratio above 10
    /// between two movable bodies (the light one's contacts give way under
    /// the heavy one), or a body that crosses half the thinnest other body
    /// in one step (a tunnelling scene). Only the study's default grid reads
    /// it: `advise` searches such a knob in every scene.
    Penetration,
}

/// `friction_model`.
pub const FRICTION_MODEL: &[&str] = &["millington", "kinetic-direction", "velocity-scaling"];
/// `velocity_limit`.
pub const VELOCITY_LIMIT: &[&str] = &["0", "0.25", "1"];
/// `relaxation`.
pub const RELAXATION: &[&str] = &["0.5"];
/// `projection`.
pub const PROJECTION: &[&str] = &["linear", "nonlinear"];
/// `position_epsilon`.
pub const POSITION_EPSILON: &[&str] = &["0.1", "0.001"];
/// `velocity_epsilon`.
pub const VELOCITY_EPSILON: &[&str] = &["0.1", "0.001"];
/// `restitution_from`.
pub const RESTITUTION_FROM: &[&str] = &["current", "initial"];
/// `dt`.
pub const DT: &[&str] = &["1/30", "1/60", "1/120", "1/240", "1/480"];
/// `ccd`.
pub const CCD: &[&str] = &["none", "bisection", "conservative"];
/// `box_box`.
pub const BOX_BOX: &[&str] = &["single", "manifold"];
/// `narrow_phase`.
pub const NARROW_PHASE: &[&str] = &["analytic", "gjk"];
/// `rollback`: the lecture's projection against rolling back to the time
/// of collision, in the scenes where a pair can be found deep and closing.
pub const ROLLBACK: &[&str] = &["projection", "rollback"];
/// `sleep`.
pub const SLEEP: &[&str] = &["true", "false"];
