//! The full verdict matrix (`study --verdicts`, docs/study.md): every scene
//! at its full size under every solver of the `solver` knob's list, printed
//! as the text matrix (`--nocapture`), with the facts the issue and
//! docs/simulate.md state held: every cell ran, warm-started sequential
//! impulses hold the slender box that the lecture's deepest-first order
//! rocks, and the friction ramp's verdicts match the closed form for every
//! solver that passes it. The figures are in docs/measurements.md.

use std::sync::atomic::AtomicBool;

use contact_lab::format::Fmt;
use contact_lab::render::study::verdicts as render;
use contact_lab::study::verdicts::criteria::SCENES;
use contact_lab::study::verdicts::{self, Matrix, Size, Verdict};

fn verdict<'a>(m: &'a Matrix, scene: &str, solver: &str) -> &'a Verdict {
    let row = m
        .rows
        .iter()
        .position(|&(s, _)| SCENES[s].id == scene)
        .unwrap();
    let col = m.columns.iter().position(|c| c == solver).unwrap();
    m.cells[row][col].as_ref().unwrap()
}

#[test]
fn the_full_verdict_matrix() {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let m = verdicts::run(Size::Full, threads, &AtomicBool::new(false), &|_, _, _| {});
    println!("{}", render::text(&m, &Fmt::new(3), 0));
    assert_eq!(m.not_run, 0);
    // No run blows up under the lecture's order or sequential impulses;
    // the substepped solvers' blow-ups (XPBD under test, the soft step on
    // the full confined crowd) are fails the matrix shows as "blew up".
    let blown: Vec<_> = m
        .verdicts()
        .filter(|v| v.failure.is_some())
        .map(|v| format!("{} under {}", v.scene, v.solver))
        .collect();
    assert!(
        m.verdicts().all(|v| v.failure.is_none()
            || (matches!(v.solver.as_str(), "xpbd" | "soft-step") && !v.pass)),
        "a run blew up: {blown:?}"
    );
    println!("blown up: {blown:?}");
    // The lecture's order rocks the slender box; warm-started sequential
    // impulses stand it still (docs/simulate.md, "Gap contacts").
    assert!(!verdict(&m, "slender-box", "deepest-first").pass);
    assert!(verdict(&m, "slender-box", "sequential-impulse+warm").pass);
    // A solver that passes the ramp matches the closed form for every box
    // (the measured figure is the worst box's distance to it).
    let ramp: Vec<&Verdict> = m
        .verdicts()
        .filter(|v| v.scene == "friction-ramp")
        .collect();
    assert!(ramp.iter().any(|v| v.pass), "no solver passes the ramp");
    for v in ramp {
        assert_eq!(v.pass, v.measured <= 0.05, "{v:?}");
    }
}
