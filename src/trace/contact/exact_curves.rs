//! The impulse-space curves of an integrated impact (u_n, u_t against P_n)
//! and the phase changes to mark on them, for the figure.

use crate::knobs::Choice;
use crate::physics::exact::{Phase, PhaseKind};
use crate::physics::Solution;
use crate::trace::ImpactCurves;

/// What a phase change is called on the figure.
fn event_label(kind: &PhaseKind<f64>) -> Option<&'static str> {
    Some(match kind {
        PhaseKind::SlipHalts => "halts",
        PhaseKind::SlipReverses { .. } => "reverses",
        PhaseKind::SlipResumes { .. } => "resumes",
        PhaseKind::SlipStarts { .. } => "starts to slip",
        PhaseKind::MaxCompression => "max compression",
        PhaseKind::Sticks { .. } => "sticks",
        PhaseKind::Slides { .. } | PhaseKind::Frictionless => return None,
    })
}

/// The events of the phases: every instant, and where sticking begins after
/// the first impulse (not where it goes on past maximum compression);
/// coinciding ones joined ("halts, sticks").
fn events(phases: &[Phase<f64>]) -> Vec<(f64, String)> {
    let mut out: Vec<(f64, String)> = Vec::new();
    let mut was_stuck = false;
    for p in phases {
        let sticks = matches!(p.kind, PhaseKind::Sticks { .. });
        let continues = sticks && (was_stuck || p.from_pn == 0.0);
        if !p.kind.is_instant() {
            was_stuck = sticks;
        }
        let Some(label) = event_label(&p.kind).filter(|_| !continues) else {
            continue;
        };
        match out.last_mut() {
            Some((at, text)) if *at == p.from_pn => {
                if !text.contains(label) {
                    text.push_str(", ");
                    text.push_str(label);
                }
            }
            _ => out.push((p.from_pn, label.to_string())),
        }
    }
    out
}

/// The curves of the `exact_impact` stage; `None` when it did not run.
pub fn impact_curves(solution: &Solution<f64>) -> Option<ImpactCurves> {
    let x = solution.exact.as_ref()?.as_ref().ok()?;
    let o = &x.outcome;
    if !o.closing {
        return None;
    }
    Some(ImpactCurves {
        law: Some(o.law).name().to_string(),
        samples: o
            .samples
            .iter()
            .map(|s| [s.p.x, s.u.x, s.u.y, s.u.z])
            .collect(),
        events: events(&o.phases),
    })
}
