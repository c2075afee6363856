//! The two choices of continuous detection ("Lecture IV Collisions", the
//! time issue): how a step finds a collision between its two poses
//! ([`Ccd`], the `ccd` knob), and what is done with a pair found
//! interpenetrating ([`Rollback`], the `rollback` knob).

use crate::physics::detect::ToiMethod;

/// How the step looks for collisions inside it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Ccd {
    /// Detect at the poses only (default): a fast small body can tunnel.
    #[default]
    None,
    /// The lecture's bisection of [t₀, t₁] (with the step sampled first,
    /// since bisection needs a collision at the interval's end).
    Bisection,
    /// Conservative advancement: distance / bound on the closing speed.
    Conservative,
}

impl Ccd {
    pub const ALL: [Ccd; 3] = [Ccd::None, Ccd::Bisection, Ccd::Conservative];

    /// The time-of-collision search this mode runs, if any.
    pub fn method(self) -> Option<ToiMethod> {
        match self {
            Ccd::None => None,
            Ccd::Bisection => Some(ToiMethod::Bisection),
            Ccd::Conservative => Some(ToiMethod::Conservative),
        }
    }
}

/// What is done with a pair that the step finds interpenetrating.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Rollback {
    /// The lecture's: the position phase projects the bodies apart (default).
    #[default]
    Projection,
    /// The lecture's question, "why not just roll back time?": the pair is
    /// moved back along its motion to its time of collision, then resolved
    /// there (the position phase has nothing left to do for it).
    Rollback,
}

/// Which normal a penetrating contact between two convex bodies takes in a
/// scene's step ("Lecture IV Collisions": for fast motion, take the normal
/// from the previous frame).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum NormalFrom {
    /// The least penetration where the bodies are now (default).
    #[default]
    Current,
    /// The direction from the closest points one frame earlier, when the
    /// pair was apart, with the depth of the overlap along it.
    Previous,
}
