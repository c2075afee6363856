//! The figure as a stage sees it: the state the stage works on. Before the
//! impulse is applied the bodies move as they came in (velocities and spins
//! before, no impulse until stage 4 finds it); the stage that applies it
//! shows before and after; from then on only after. The projection's move
//! (outlines after, travel) appears from the projection stage on.

use super::model::{ArrowKind, Figure, LegendItem};
use crate::physics::StageId;

/// Where a stage stands in the story of the contact.
fn order(stage: StageId) -> usize {
    StageId::ALL.iter().position(|s| *s == stage).unwrap_or(0)
}

impl Figure {
    /// This figure reduced to what `stage` works on (see the module note).
    pub fn at_stage(mut self, stage: StageId) -> Figure {
        let at = order(stage);
        let impulse_found = at >= order(StageId::Impulse);
        let applied = at >= order(StageId::ApplyImpulse);
        let applying = stage == StageId::ApplyImpulse;
        let projected = at >= order(StageId::NonlinearProjection);
        let before = !applied || applying;
        self.arrows.retain(|a| match a.kind {
            ArrowKind::Impulse | ArrowKind::Reaction => impulse_found,
            ArrowKind::Velocity => before,
            ArrowKind::VelocityAfter => applied,
            ArrowKind::Arm | ArrowKind::Normal => true,
        });
        self.spins
            .retain(|s| if s.after { applied } else { before });
        // Arrows and spins to the scale of the speeds this stage shows: a
        // set-up scaled with the speeds after the impulse would give their
        // size away (the arrows' lengths and which spins are worth drawing).
        self.top_speed = self
            .bodies
            .iter()
            .flat_map(|b| [(b.speed, before), (b.speed_after, applied)])
            .filter(|(_, shown)| *shown)
            .map(|(speed, _)| speed)
            .fold(0.0, f64::max);
        if !projected {
            // Before the projection the bodies have not moved: no outline
            // after, no move from p to p′ (which the question asks for).
            for b in &mut self.bodies {
                b.outline_after = None;
                b.centre_after = b.centre;
                b.pose_change = 0.0;
                b.travel = 0.0;
            }
        }
        self.legend.retain(|item| match item {
            LegendItem::Impulse { .. } | LegendItem::Reaction { .. } => impulse_found,
            LegendItem::Moved | LegendItem::Travel { .. } => projected,
            _ => true,
        });
        self.prune_legend();
        self
    }

    /// Leaves out legend entries whose mark is not drawn: a spin about an
    /// axis the view does not show, a velocity with no arrow.
    pub(super) fn prune_legend(&mut self) {
        let spins = &self.spins;
        let arrows = &self.arrows;
        self.legend.retain(|item| match item {
            LegendItem::Spin { body, .. } => spins.iter().any(|s| s.body == *body),
            LegendItem::Velocity { body, .. } => arrows.iter().any(|a| {
                a.body == Some(*body)
                    && matches!(a.kind, ArrowKind::Velocity | ArrowKind::VelocityAfter)
            }),
            _ => true,
        });
    }
}
