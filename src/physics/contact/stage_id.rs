//! The stages of one contact's resolution, in the lecture's order. Their JSON
//! names are written here and nowhere else; titles and labels live in the trace.

/// One resolution stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum StageId {
    ContactFrame,
    UnitImpulse,
    DesiredDeltaVelocity,
    Impulse,
    FrictionClamp,
    ApplyImpulse,
    NonlinearProjection,
    OrientationUpdate,
    ExactImpact,
    Checks,
}

impl StageId {
    /// Every stage, in order.
    pub const ALL: [StageId; 10] = [
        StageId::ContactFrame,
        StageId::UnitImpulse,
        StageId::DesiredDeltaVelocity,
        StageId::Impulse,
        StageId::FrictionClamp,
        StageId::ApplyImpulse,
        StageId::NonlinearProjection,
        StageId::OrientationUpdate,
        StageId::ExactImpact,
        StageId::Checks,
    ];

    /// The id in JSON, lesson `[[printed]]` entries and the command line.
    pub fn json_name(self) -> &'static str {
        match self {
            StageId::ContactFrame => "contact_frame",
            StageId::UnitImpulse => "unit_impulse",
            StageId::DesiredDeltaVelocity => "desired_delta_velocity",
            StageId::Impulse => "impulse",
            StageId::FrictionClamp => "friction_clamp",
            StageId::ApplyImpulse => "apply_impulse",
            StageId::NonlinearProjection => "nonlinear_projection",
            StageId::OrientationUpdate => "orientation_update",
            StageId::ExactImpact => "exact_impact",
            StageId::Checks => "checks",
        }
    }

    /// The stage with this JSON name.
    pub fn from_json_name(name: &str) -> Option<StageId> {
        Self::ALL.into_iter().find(|s| s.json_name() == name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_are_unique() {
        for s in StageId::ALL {
            assert_eq!(StageId::from_json_name(s.json_name()), Some(s));
        }
        let mut names: Vec<_> = StageId::ALL.iter().map(|s| s.json_name()).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), StageId::ALL.len());
        assert_eq!(StageId::from_json_name("nope"), None);
    }
}
