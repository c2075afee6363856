//! What each stage is called: the full title of the worked solution and the
//! short label of the TUI's stage list.

use crate::physics::StageId;

impl StageId {
    /// The heading of the stage in worked solutions.
    pub fn title(self) -> &'static str {
        match self {
            StageId::ContactFrame => "Contact frame",
            StageId::UnitImpulse => "Velocity change per unit impulse",
            StageId::DesiredDeltaVelocity => "Desired change in velocity",
            StageId::Impulse => "Impulse",
            StageId::FrictionClamp => "Friction clamp",
            StageId::ApplyImpulse => "Applying the impulse",
            StageId::NonlinearProjection => "Resolving interpenetration",
            StageId::OrientationUpdate => "Orientation update",
            StageId::ExactImpact => "Exact impact integration",
            StageId::Checks => "Checks",
        }
    }

    /// A short name for lists.
    pub fn label(self) -> &'static str {
        match self {
            StageId::ContactFrame => "Contact frame",
            StageId::UnitImpulse => "Unit impulse",
            StageId::DesiredDeltaVelocity => "Desired Δv",
            StageId::Impulse => "Impulse",
            StageId::FrictionClamp => "Friction",
            StageId::ApplyImpulse => "Apply impulse",
            StageId::NonlinearProjection => "Projection",
            StageId::OrientationUpdate => "Orientation",
            StageId::ExactImpact => "Integration",
            StageId::Checks => "Checks",
        }
    }
}
