//! What each stage is called: the full title of the worked solution, the
//! short label of the TUI's stage list, and the one sentence that says why
//! the stage exists and how it follows from the one before.

use crate::physics::StageId;

impl StageId {
    /// The stage's number as the worked solution, the TUI legend and the
    /// glossary show it (1 contact frame … 10 checks), from `StageId::ALL`.
    pub fn number(self) -> usize {
        StageId::ALL.iter().position(|x| *x == self).unwrap_or(0) + 1
    }

    /// The short label in running text: its first letter lowered and
    /// nothing else ("Desired Δv" → "desired Δv", never "desired δv").
    pub fn label_in_text(self) -> String {
        let label = self.label();
        let mut chars = label.chars();
        match chars.next() {
            Some(first) => first.to_lowercase().chain(chars).collect(),
            None => String::new(),
        }
    }

    /// Every stage numbered, for legends: "1 contact frame, 2 unit impulse, …
    /// 10 checks" (`label` maps a stage's text, e.g. to LaTeX).
    pub fn numbered_list(label: impl Fn(&str) -> String) -> String {
        StageId::ALL
            .iter()
            .map(|s| format!("{} {}", s.number(), label(&s.label_in_text())))
            .collect::<Vec<_>>()
            .join(", ")
    }

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

    /// Why the stage exists, in one sentence that ties it to the stage
    /// before: shown above the formulas ("why before how").
    pub fn why(self) -> &'static str {
        match self {
            StageId::ContactFrame => "An impulse is easiest to find along the contact normal, so we first set up axes at the contact point q (x along the normal d̂, two tangents t₀, t₁) and the arms r from each body's centre to q; every later stage works with these.",
            StageId::UnitImpulse => "Before knowing how large the impulse must be, we ask how much ONE unit of impulse along d̂ would change the closing speed at q: the linear part 1/m plus the part from the turn it causes about the arms r of stage 1.",
            StageId::DesiredDeltaVelocity => "The impulse must change the normal speed at q by a known amount: we measure how fast the contact points approach now (v_s) and, with restitution c, the change Δv that makes them separate as the material bounces.",
            StageId::Impulse => "Dividing the change we want (Δv, stage 3) by the change one unit of impulse makes (Δq̇_t, stage 2) gives the size of the impulse g; with friction the 3×3 matrix M does the same for all three directions at once.",
            StageId::FrictionClamp => "Friction can push only so hard (Coulomb: at most μ times the normal impulse), so the impulse of stage 4 is tested against that limit and, if it asks for more, cut back to sliding friction.",
            StageId::ApplyImpulse => "The impulse of stages 4–5 now changes each body's motion: its velocity by g/m and its spin by I⁻¹(r × g), with body 2 receiving -g.",
            StageId::NonlinearProjection => "The velocities are now right, but the bodies still overlap by d_pen; this stage moves and turns them apart, sharing the depth by how easily each body moves along d̂ (the same inertia as stage 2).",
            StageId::OrientationUpdate => "The turn Δθ of stage 7 still has to be added to each body's orientation quaternion θ: the first-order update θ + ½[0, Δθ]θ, then normalised.",
            StageId::ExactImpact => "Stages 4–5 find the impulse in one shot; integrating the impact as the normal impulse P_n grows, with friction always against the current slip, shows what really happens when slip halts, sticks or reverses, and how far the one-shot answer is from it (it applies nothing: the bodies stay as stage 6 left them).",
            StageId::Checks => "A worked solution should prove itself: the results of stages 1–8 are tested against the laws they must obey (momentum, the restitution target, energy, the friction cone, the penetration left).",
        }
    }
}
