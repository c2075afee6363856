//! Small command-line answers (issue 23, item 8): `glossary --help` does
//! not advertise an option it refuses; `solve` on a scene says it is a scene
//! and suggests `simulate`; `--seconds` beyond the step limit names the limit
//! in scientific notation.

use assert_cmd::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn glossary_help_does_not_advertise_fragment() {
    let (code, help, _) = run(&["glossary", "--help"]);
    assert_eq!(code, 0);
    assert!(help.contains("latex"), "{help}");
    assert!(!help.contains("--fragment"), "{help}");
    let (code, _, err) = run(&["glossary", "--fragment"]);
    assert_eq!(code, 2, "{err}");
    // solve, which takes it, still says what it does.
    let (_, help, _) = run(&["solve", "--help"]);
    assert!(help.contains("--fragment"), "{help}");
}

#[test]
fn solve_on_a_scene_says_it_is_a_scene_and_suggests_simulate() {
    for command in ["solve", "figure"] {
        let (code, out, err) = run(&[command, "stack-5"]);
        assert_eq!(code, 2, "{command}: {err}");
        assert!(out.is_empty());
        assert!(err.contains("'stack-5' is a scene"), "{command}: {err}");
        assert!(
            err.contains("contact-lab simulate stack-5"),
            "{command}: {err}"
        );
        assert!(!err.contains("has 0 contact(s)"), "{command}: {err}");
    }
}

#[test]
fn seconds_beyond_the_step_limit_name_the_limit_in_scientific_notation() {
    let (code, _, err) = run(&["simulate", "ball-drop", "--seconds", "1e300"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--seconds 1e300 at dt = ")
            && err.contains("over the limit of 10000000 steps"),
        "{err}"
    );
    assert!(err.len() < 200, "{err}");
    let (code, _, err) = run(&["study", "--seconds", "1e300"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("at most 60 s, got 1e300"), "{err}");
}

#[test]
fn a_study_beyond_its_caps_asks_for_force() {
    let (code, out, err) = run(&[
        "study",
        "ball-drop",
        "--grid",
        "dt=0.00001",
        "--seconds",
        "60",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("simulated steps") && err.contains("over the cap of 10 million steps"),
        "{err}"
    );
    assert!(err.contains("--force"), "{err}");
    let budgets: Vec<String> = (1..=60).map(|k| k.to_string()).collect();
    let epsilons: Vec<String> = (1..=40).map(|k| format!("0.00{k}")).collect();
    let (code, _, err) = run(&[
        "study",
        "--grid",
        &format!("budget={}", budgets.join(",")),
        "--grid",
        &format!("position_epsilon={}", epsilons.join(",")),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("configurations, over the cap of 2,000 configurations"),
        "{err}"
    );
}

/// A 10⁶-configuration grid is refused before its cross product is built
/// (building it took minutes).
#[test]
fn a_million_configuration_grid_is_refused_at_once() {
    let relaxations: Vec<String> = (1..=1000)
        .map(|k| format!("{}", k as f64 / 1000.0))
        .collect();
    let budgets: Vec<String> = (1..=1000).map(|k| k.to_string()).collect();
    let (code, out, err) = run(&[
        "study",
        "ball-drop",
        "--grid",
        &format!("relaxation={}", relaxations.join(",")),
        "--grid",
        &format!("budget={}", budgets.join(",")),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("up to 1000000 configurations, over the cap of 2,000 configurations"),
        "{err}"
    );
}

#[test]
fn a_run_beyond_its_cap_asks_for_force() {
    let (code, out, err) = run(&["simulate", "sphere-row-20", "--steps", "10000000"]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty());
    assert!(
        err.contains("10000000 steps of 20 movable bodies, over the cap of 100 million"),
        "{err}"
    );
    assert!(err.contains("--force"), "{err}");
}

#[test]
fn progress_is_shown_only_on_a_terminal() {
    // stderr is a pipe here: the run says nothing there.
    let (code, out, err) = run(&["simulate", "ball-drop", "--steps", "3000"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("ball-drop"));
    assert!(err.is_empty(), "{err}");
}
