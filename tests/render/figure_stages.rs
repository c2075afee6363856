//! The picture follows the stage (issue 16, item 7): before the impulse is
//! applied it shows the velocities before (and the impulse only once stage 4
//! finds it), the applying stage before and after, later stages after; the
//! projection's move only from the projection stage. And every legend entry
//! names a mark that is drawn.

use crate::common;

use contact_lab::lesson::Lesson;
use contact_lab::physics::StageId;
use contact_lab::render::figure::{ArrowKind, Figure, LegendItem, Plane};

fn order(s: StageId) -> usize {
    StageId::ALL.iter().position(|x| *x == s).unwrap()
}

/// `Err` naming the first legend entry without its mark.
fn legend_is_drawn(f: &Figure) -> Result<(), String> {
    let arrow = |kind: ArrowKind, body: Option<usize>, contact: Option<usize>| {
        f.arrows.iter().any(|a| {
            a.kind == kind
                && (body.is_none() || a.body == body)
                && (contact.is_none() || a.contact == contact)
        })
    };
    for item in &f.legend {
        let ok = match item {
            LegendItem::Impulse { contact, .. } => arrow(ArrowKind::Impulse, None, Some(*contact)),
            LegendItem::Reaction { contact } => arrow(ArrowKind::Reaction, None, Some(*contact)),
            LegendItem::Normal { contact, .. } => arrow(ArrowKind::Normal, None, Some(*contact)),
            LegendItem::Arm { body, .. } => arrow(ArrowKind::Arm, Some(*body), None),
            LegendItem::Velocity { body, .. } => {
                arrow(ArrowKind::Velocity, Some(*body), None)
                    || arrow(ArrowKind::VelocityAfter, Some(*body), None)
            }
            LegendItem::Spin { body, .. } => f.spins.iter().any(|s| s.body == *body),
            LegendItem::Moved => f.bodies.iter().any(|b| b.outline_after.is_some()),
            _ => true,
        };
        if !ok {
            return Err(format!("legend {item:?} has no mark"));
        }
    }
    Ok(())
}

#[test]
fn every_stage_shows_the_state_it_works_on_and_its_legend_is_drawn() {
    let mut figures = 0;
    common::each_contact_in_each_plane(|id, k, t, plane| {
        let whole = Figure::of_contact(&t.scene, plane);
        for stage in StageId::ALL {
            let f = whole.clone().at_stage(stage);
            let at = order(stage);
            let kinds: Vec<ArrowKind> = f.arrows.iter().map(|a| a.kind).collect();
            let ctx = format!("{id} #{k} {plane:?} {}", stage.json_name());
            if at < order(StageId::Impulse) {
                assert!(
                    !kinds.contains(&ArrowKind::Impulse),
                    "{ctx}: impulse too early"
                );
            }
            if at < order(StageId::ApplyImpulse) {
                assert!(
                    !kinds.contains(&ArrowKind::VelocityAfter),
                    "{ctx}: after too early"
                );
                assert!(f.spins.iter().all(|s| !s.after), "{ctx}");
            }
            if at > order(StageId::ApplyImpulse) {
                assert!(
                    !kinds.contains(&ArrowKind::Velocity),
                    "{ctx}: before too late"
                );
                assert!(f.spins.iter().all(|s| s.after), "{ctx}");
            }
            if at < order(StageId::NonlinearProjection) {
                assert!(f.bodies.iter().all(|b| b.outline_after.is_none()), "{ctx}");
            }
            if let Err(e) = legend_is_drawn(&f) {
                panic!("{ctx}: {e}");
            }
            figures += 1;
        }
        legend_is_drawn(&whole).unwrap();
    });
    assert!(figures > 500, "{figures}");
}

#[test]
fn the_applying_stage_shows_before_and_after() {
    let l = Lesson::load("lecture-2").unwrap();
    let t = contact_lab::worked_solution(&l, 0);
    let f = Figure::of_contact(&t.scene, Plane::Xy).at_stage(StageId::ApplyImpulse);
    let kinds: Vec<ArrowKind> = f.arrows.iter().map(|a| a.kind).collect();
    assert!(kinds.contains(&ArrowKind::Velocity));
    assert!(kinds.contains(&ArrowKind::VelocityAfter));
    assert!(kinds.contains(&ArrowKind::Impulse));
    let before = Figure::of_contact(&t.scene, Plane::Xy).at_stage(StageId::DesiredDeltaVelocity);
    assert!(!before.arrows.iter().any(|a| a.kind == ArrowKind::Impulse));
}
