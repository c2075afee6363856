//! The substepped solvers (soft step, XPBD) through the binary: `resolve`
//! refuses them with why (exit 2: they have no single-instant answer), and
//! `simulate` says before the run what they do not do (continuous
//! detection, the tunnelling and energy audits) and, for XPBD, the figures
//! that miss their closed forms — never silent.

use crate::common::cli::run;

#[test]
fn resolve_refuses_a_time_stepper_and_says_why() {
    for (solver, why) in [("soft-step", "soft step"), ("xpbd", "time stepper")] {
        let r = run(&["resolve", "lecture-2", "--solver", solver]);
        assert_eq!(r.code, Some(2), "{solver}: {}", r.stderr);
        assert!(r.stdout.is_empty(), "{solver}: {}", r.stdout);
        assert!(
            r.stderr.contains(why) && r.stderr.contains("no single-instant answer"),
            "{solver}: {}",
            r.stderr
        );
        assert!(
            r.stderr.contains(&format!("--solver {solver}")),
            "{}",
            r.stderr
        );
    }
}

#[test]
fn simulate_says_what_a_substepped_solver_does_not_do() {
    for solver in ["soft-step", "xpbd"] {
        let r = run(&["simulate", "ball-drop", "--solver", solver, "--steps", "3"]);
        assert_eq!(r.code, Some(0), "{solver}: {}", r.stderr);
        assert!(
            r.stderr
                .contains("the tunnelling audit and the energy audits do not run"),
            "{solver}: {}",
            r.stderr
        );
        assert_eq!(
            r.stderr.contains("is under test"),
            solver == "xpbd",
            "{}",
            r.stderr
        );
    }
    let r = run(&["simulate", "ball-drop", "--steps", "3"]);
    assert!(!r.stderr.contains("audits do not run"), "{}", r.stderr);
}
