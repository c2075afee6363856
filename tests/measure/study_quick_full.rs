//! issue 27's check "quick and full agree on each scene's verdict, or quick
//! says that its grid is partial", on all nine of the study's default
//! scenes at their default lengths (tests/cli/advise.rs checks stack-5 at
//! 0.5 s in the debug build). Untimed: the verdict's comparison of the
//! solvers is on error at equal work, which timing does not move.

use std::time::Instant;

use crate::common::advise::lesson;
use contact_lab::study::{grid, sweep};

/// The verdict's comparison of the solvers at equal work, if it makes one:
/// both errors and the winner, to the sentence's end (a full stop and a
/// space, or the last character: the errors have decimal points).
fn solvers(verdict: &str) -> Option<String> {
    verdict.split("; at equal work").nth(1).map(|s| {
        let s = s.split(". ").next().unwrap_or("");
        s.strip_suffix('.').unwrap_or(s).to_string()
    })
}

#[test]
fn quick_and_full_compare_the_solvers_alike_on_every_default_scene_and_quick_says_partial() {
    let specs: Vec<sweep::SceneSpec> = grid::SCENES
        .iter()
        .map(|&(id, seconds, reference_solver)| sweep::SceneSpec {
            lesson: lesson(id),
            seconds,
            reference_solver,
        })
        .collect();
    let run = |quick| {
        let o = sweep::Options {
            timed: false,
            repeats: 1,
            quick,
            grid: Vec::new(),
        };
        let start = Instant::now();
        let s = sweep::study(&specs, &o, &mut |_, _| {});
        println!("quick {quick}: {:.1} s", start.elapsed().as_secs_f64());
        s
    };
    let (q, f) = (run(true), run(false));
    assert_eq!(q.scenes.len(), grid::SCENES.len());
    let mut compared = 0;
    for (q, f) in q.scenes.iter().zip(&f.scenes) {
        assert_eq!(q.scene, f.scene);
        println!(
            "{:<18} quick {} rows, full {}: {}",
            q.scene,
            q.rows.len(),
            f.rows.len(),
            solvers(&f.verdict).unwrap_or_else(|| "(no comparison)".into())
        );
        assert_eq!(solvers(&q.verdict), solvers(&f.verdict), "{}", q.scene);
        compared += usize::from(solvers(&f.verdict).is_some());
        assert!(
            q.partial.is_some_and(|n| n > 0) && q.verdict.contains("partial"),
            "{}: {}",
            q.scene,
            q.verdict
        );
        assert!(f.partial.is_none() && !f.verdict.contains("partial"));
    }
    assert!(compared > 0, "some scene compares the solvers");
    // The winner is named (the sentence was not cut at an error's decimal point).
    let winner = solvers(&f.scenes[2].verdict).unwrap();
    assert!(winner.contains(" m: "), "stack-5: {winner}");
}
