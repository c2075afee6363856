//! The broad-phase study timed (docs/study.md, "The broad phase"): sort and
//! sweep, the uniform grid and the dynamic tree on 10 to 10,000 bodies,
//! scattered and clustered. Writes the Markdown report to
//! `$CARGO_TARGET_TMPDIR/broad-phase-study.md` and prints it
//! (`--nocapture`). Asserts counts only, never times: every method keeps the
//! same pairs; at 10,000 scattered bodies the grid and the tree test fewer
//! than one pair in 2,000 of all-against-all's; in the cluster the grid's
//! large bodies are loose and it tests more than the sweep.

use contact_lab::format::Fmt;
use contact_lab::render::study::broad as render;
use contact_lab::study::broad::{run, Case, COUNTS};

#[test]
fn broad_phase_study_report() {
    let study = run(&COUNTS, true, &mut |_, _| {});
    let report = render::text(&study, &Fmt::new(3), true);
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("broad-phase-study.md");
    std::fs::write(&path, &report).unwrap();
    println!("{report}\n(written to {})", path.display());
    for p in &study.points {
        let kept = p.rows[0].kept;
        assert!(p.rows.iter().all(|r| r.kept == kept), "{p:?}");
        assert!(p.rows.iter().all(|r| r.microseconds.is_some()));
    }
    let at = |case: Case, n: usize, method: &str| {
        let p = study
            .points
            .iter()
            .find(|p| p.case == case && p.bodies == n)
            .unwrap();
        (
            p.all_pairs,
            p.rows.iter().find(|r| r.method == method).unwrap().clone(),
        )
    };
    for method in ["grid", "bvh"] {
        let (all, r) = at(Case::Scattered, 10_000, method);
        assert!(r.tests * 2000 < all, "{method}: {r:?}");
    }
    let (_, grid) = at(Case::Clustered, 10_000, "grid");
    let (_, sweep) = at(Case::Clustered, 10_000, "sweep");
    assert_eq!(grid.loose, 2000);
    assert!(grid.tests > sweep.tests, "{grid:?} {sweep:?}");
}
