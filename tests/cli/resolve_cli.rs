//! `contact-lab resolve` through the binary: the JSON contract of docs/resolve.md,
//! `--log`, `--repeat`, `--show`, the implementation flag, bad settings in a
//! lesson (65, file:line:column, naming the field), bad flags (2), bad
//! lessons reported exactly as `solve` reports them, and `solve
//! --all-contacts` pointing to `resolve`.

use std::path::Path;

use serde_json::Value as J;

use crate::common::cli::run;

fn json(args: &[&str]) -> J {
    let r = run(args);
    assert_eq!(r.code, Some(0), "{args:?}: {}", r.stderr);
    serde_json::from_str(&r.stdout).expect("JSON")
}

fn keys(v: &J) -> Vec<&str> {
    v.as_object().unwrap().keys().map(String::as_str).collect()
}

#[test]
fn json_follows_the_contract() {
    let v = json(&["resolve", "box-four-corners", "--format", "json"]);
    assert_eq!(
        keys(&v),
        ["lesson", "contacts", "position", "velocity", "seconds", "after"]
    );
    assert_eq!(v["lesson"], "box-four-corners");
    assert_eq!(v["contacts"], 4);
    assert_eq!(
        keys(&v["position"]),
        [
            "iterations_used",
            "iteration_limit",
            "epsilon",
            "max_penetration_before",
            "max_penetration_after"
        ]
    );
    assert_eq!(
        keys(&v["velocity"]),
        [
            "iterations_used",
            "iteration_limit",
            "epsilon",
            "max_desired_before",
            "max_desired_after"
        ]
    );
    assert_eq!(v["position"]["iteration_limit"], 32);
    assert_eq!(v["position"]["epsilon"], 0.01);
    assert_eq!(v["position"]["max_penetration_before"], 0.07);
    assert_eq!(keys(&v["seconds"]), ["prepare", "position", "velocity"]);
    for phase in ["prepare", "position", "velocity"] {
        let s = v["seconds"][phase].as_f64().unwrap();
        assert!((0.0..1.0).contains(&s), "{phase}: {s}");
    }
    assert_eq!(keys(&v["after"]), ["box"]);
    assert_eq!(
        keys(&v["after"]["box"]),
        ["position", "orientation", "velocity", "angular_velocity"]
    );
    assert_eq!(
        v["after"]["box"]["orientation"].as_array().unwrap().len(),
        4
    );
}

#[test]
fn the_log_has_every_iteration_with_the_contacts_it_changed() {
    let v = json(&["resolve", "box-four-corners", "--format", "json", "--log"]);
    let log = v["position"]["log"].as_array().unwrap();
    assert_eq!(
        log.len() as u64,
        v["position"]["iterations_used"].as_u64().unwrap()
    );
    assert_eq!(
        keys(&log[0]),
        ["iteration", "contact", "penetration", "updated"]
    );
    // The deepest corner first; the other three change.
    assert_eq!(log[0]["contact"], 0);
    assert_eq!(log[0]["penetration"], 0.07);
    let updated: Vec<u64> = log[0]["updated"]
        .as_array()
        .unwrap()
        .iter()
        .map(|u| u[0].as_u64().unwrap())
        .collect();
    assert_eq!(updated, [1, 2, 3]);
    // Each iteration takes the contact its predecessor left deepest.
    for pair in log.windows(2) {
        let next = pair[1]["contact"].as_u64().unwrap();
        let deepest = pair[0]["updated"]
            .as_array()
            .unwrap()
            .iter()
            .max_by(|a, b| a[1].as_f64().partial_cmp(&b[1].as_f64()).unwrap())
            .unwrap();
        assert_eq!(deepest[0].as_u64().unwrap(), next);
        assert_eq!(deepest[1], pair[1]["penetration"]);
    }
    let vlog = v["velocity"]["log"].as_array().unwrap();
    assert_eq!(
        keys(&vlog[0]),
        [
            "iteration",
            "contact",
            "desired",
            "impulse_contact",
            "updated"
        ]
    );
}

#[test]
fn both_implementations_and_every_repeat_give_the_same_state() {
    let indexed = json(&["resolve", "box-stack", "--format", "json", "--log"]);
    let scan = json(&[
        "resolve",
        "box-stack",
        "--format",
        "json",
        "--log",
        "--implementation",
        "scan",
        "--repeat",
        "3",
    ]);
    for key in ["position", "velocity", "after"] {
        assert_eq!(indexed[key], scan[key], "{key}");
    }
}

#[test]
fn zero_iterations_resolve_nothing() {
    let r = run(&[
        "resolve",
        "box-four-corners",
        "--position-iterations",
        "0",
        "--velocity-iterations",
        "0",
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(r
        .stdout
        .contains("The position iteration limit is 0: nothing was resolved."));
    assert!(r
        .stdout
        .contains("The velocity iteration limit is 0: nothing was resolved."));
    assert!(
        r.stdout.contains("box: position (0, 0.46186, 0)"),
        "{}",
        r.stdout
    );
}

#[test]
fn a_limit_that_is_reached_is_said() {
    let r = run(&["resolve", "box-stack"]);
    assert!(
        r.stdout
            .contains("velocity iteration limit 96 reached: largest desired Δv left"),
        "{}",
        r.stdout
    );
}

#[test]
fn show_gives_the_worked_solution_of_that_iterations_contact() {
    // The first iteration of the lecture's third example on the floor is the
    // lecture's own third example: same bodies, same penetration.
    let shown = json(&[
        "resolve",
        "third-example-floor",
        "--show",
        "position:0",
        "--format",
        "json",
    ]);
    let lecture = json(&["solve", "lecture-3", "--format", "json"]);
    let stage = |v: &J, id: &str| {
        v["stages"]
            .as_array()
            .unwrap()
            .iter()
            .find(|s| s["id"] == id)
            .unwrap()["values"]
            .clone()
    };
    for id in [
        "contact_frame",
        "nonlinear_projection",
        "orientation_update",
    ] {
        assert_eq!(stage(&shown, id), stage(&lecture, id), "{id}");
    }
    // Iteration 2 takes the cube's contact again at the depth the log says,
    // with the bodies where iterations 0 and 1 left them.
    let log = json(&[
        "resolve",
        "third-example-floor",
        "--format",
        "json",
        "--log",
    ]);
    let second = &log["position"]["log"][2];
    let r = run(&["resolve", "third-example-floor", "--show", "position:2"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(r.stdout.starts_with(
        "Position iteration 2 of `resolve third-example-floor` takes contact 0: cube in sphere"
    ));
    let text_json = json(&[
        "resolve",
        "third-example-floor",
        "--show",
        "position:2",
        "--format",
        "json",
    ]);
    assert_eq!(text_json["contact"], second["contact"]);
    let depth = stage(&text_json, "nonlinear_projection")["linear_move1"]
        .as_f64()
        .unwrap()
        + stage(&text_json, "nonlinear_projection")["angular_move1"]
            .as_f64()
            .unwrap()
        - stage(&text_json, "nonlinear_projection")["linear_move2"]
            .as_f64()
            .unwrap()
        - stage(&text_json, "nonlinear_projection")["angular_move2"]
            .as_f64()
            .unwrap();
    let taken = second["penetration"].as_f64().unwrap();
    assert!((depth - taken).abs() < 1e-12, "{depth} vs {taken}");
    // A velocity iteration shows the velocities of that moment.
    let r = run(&["resolve", "newtons-cradle", "--show", "velocity:2"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(
        r.stdout
            .contains("takes contact 2: ball2 ↔ ball3 at desired Δv 4"),
        "{}",
        r.stdout
    );
    assert!(
        r.stdout.contains("= (2, 0, 0)"),
        "ball2 moves at 2 by then:\n{}",
        r.stdout
    );
}

#[test]
fn bad_flags_are_usage_errors_naming_the_flag() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["--position-iterations", "1000000001"],
            "--position-iterations: position_iterations must be a whole number from 0 to 10⁹",
        ),
        (
            &["--velocity-epsilon", "-0.1"],
            "--velocity-epsilon: velocity_epsilon must be a finite number ≥ 0, got -0.1",
        ),
        (
            &["--position-epsilon", "nan"],
            "--position-epsilon: position_epsilon must be a finite number ≥ 0, got NaN",
        ),
        (
            &["--velocity-limit", "-1"],
            "--velocity-limit: velocity_limit must be a finite number ≥ 0",
        ),
        (&["--show", "position"], "expected position:K or velocity:K"),
        (
            &["--show", "velocity:99"],
            "--show velocity:99: the velocity phase of 'box-four-corners' ran 6 iteration(s)",
        ),
        (&["--repeat", "0"], "--repeat"),
        (&["--restitution-from", "later"], "--restitution-from"),
    ];
    for (flags, message) in cases {
        let mut args = vec!["resolve", "box-four-corners"];
        args.extend_from_slice(flags);
        let r = run(&args);
        assert_eq!(r.code, Some(2), "{args:?}: {}", r.stderr);
        assert!(r.stdout.is_empty(), "{args:?}");
        assert!(
            r.stderr.contains(message),
            "{args:?}: expected «{message}» in\n{}",
            r.stderr
        );
    }
}

/// `tests/invalid_resolve/`: bad resolver settings, each with its place and message.
#[rustfmt::skip]
const SETTINGS: &[(&str, usize, usize, &str)] = &[
    ("fractional-iterations", 20, 23, "in [settings]: position_iterations must be a whole number from 0 to 10⁹ (1000000000), got 10.5"),
    ("inf-position-epsilon", 20, 20, "in [settings]: position_epsilon must be a finite number ≥ 0, got inf"),
    ("nan-velocity-epsilon", 20, 20, "in [settings]: velocity_epsilon must be a finite number ≥ 0, got NaN"),
    ("negative-position-epsilon", 20, 20, "in [settings]: position_epsilon must be a finite number ≥ 0, got -0.01"),
    ("negative-position-iterations", 20, 23, "in [settings]: position_iterations must be a whole number from 0 to 10⁹ (1000000000), got -5"),
    ("resolver-setting-in-contact", 18, 14, "velocity_epsilon is a setting of the whole scene: put it in the lesson's [settings]"),
    ("tiny-position-epsilon", 20, 20, "in [settings]: position_epsilon 1e-70 is below contact-lab's smallest non-zero magnitude, 1e-60"),
    ("unknown-restitution-from", 20, 20, "in [settings]: restitution_from must be one of \"current\", \"initial\", got \"later\""),
    ("unknown-solver", 20, 10, "in [settings]: solver must be one of \"deepest-first\", \"sequential-impulse\", \"soft-step\", \"xpbd\", \"lcp\", got \"fastest\""),
    ("velocity-iterations-past-limit", 20, 23, "in [settings]: velocity_iterations must be a whole number from 0 to 10⁹ (1000000000), got 2000000000"),
];

#[test]
fn bad_resolver_settings_exit_65_naming_the_field_and_its_place() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/invalid_resolve");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(files.len(), SETTINGS.len(), "one row per file: {files:?}");
    for (stem, line, column, message) in SETTINGS {
        let path = format!("tests/invalid_resolve/{stem}.toml");
        for command in ["resolve", "solve"] {
            let r = run(&[command, &path]);
            assert_eq!(r.code, Some(65), "{command} {path}: {}", r.stderr);
            assert!(r.stdout.is_empty());
            let first = r.stderr.lines().next().unwrap_or("");
            let at = format!("error: {path}:{line}:{column}: ");
            assert!(
                first.starts_with(&at),
                "{command}: expected `{at}…` in {first}"
            );
            assert!(
                first.contains(message),
                "{command}: expected «{message}» in {first}"
            );
        }
    }
}

#[test]
fn bad_lessons_are_reported_exactly_as_solve_reports_them() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/invalid_lessons");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert!(files.len() >= 30);
    for file in files {
        let path = format!("tests/invalid_lessons/{file}");
        let solve = run(&["solve", &path]);
        let resolve = run(&["resolve", &path]);
        assert_eq!(resolve.code, Some(65), "{path}: {}", resolve.stderr);
        assert_eq!(resolve.stderr, solve.stderr, "{path}");
        assert!(resolve.stdout.is_empty(), "{path}");
    }
    let missing = run(&["resolve", "no-such-lesson.toml"]);
    assert_eq!(missing.code, Some(66));
}

#[test]
fn solve_all_contacts_says_each_is_solved_alone_and_points_to_resolve() {
    // Unfolded (--width 0): the note's sentences on their own lines.
    let r = run(&[
        "solve",
        "box-four-corners",
        "--all-contacts",
        "--width",
        "0",
    ]);
    assert_eq!(r.code, Some(0));
    assert!(r.stdout.starts_with(
        "Each contact below is solved alone, from the scene as given: the results are independent of each other."
    ));
    assert!(r
        .stdout
        .contains("run `contact-lab resolve box-four-corners`"));
    let md = run(&[
        "solve",
        "box-four-corners",
        "--all-contacts",
        "--format",
        "md",
    ]);
    assert!(md
        .stdout
        .starts_with("> Each contact below is solved alone"));
    let tex = run(&[
        "solve",
        "box-four-corners",
        "--all-contacts",
        "--format",
        "latex",
    ]);
    assert!(tex.stdout.starts_with("\\documentclass"));
    assert!(tex
        .stdout
        .contains("\\begin{document}\n\\noindent\\emph{Each contact below is solved alone"));
    // JSON keeps its contract: an array of traces, no note.
    let all: J = serde_json::from_str(
        &run(&[
            "solve",
            "box-four-corners",
            "--all-contacts",
            "--format",
            "json",
        ])
        .stdout,
    )
    .unwrap();
    assert_eq!(all.as_array().map(Vec::len), Some(4));
    // One contact alone needs no note.
    let one = run(&["solve", "box-four-corners"]);
    assert!(!one.stdout.contains("solved alone"));
}

/// Every key of the JSON (with the log) is documented in docs/resolve.md's
/// table, and every key the table lists is produced.
#[test]
fn docs_resolve_md_lists_exactly_the_keys_produced() {
    fn collect(v: &J, out: &mut std::collections::BTreeSet<String>, under_after: bool) {
        match v {
            J::Object(m) => {
                for (k, x) in m {
                    // Body names under `after` are data, not keys.
                    if !under_after {
                        out.insert(k.clone());
                    }
                    collect(x, out, k == "after" && !under_after);
                }
            }
            J::Array(a) => a.iter().for_each(|x| collect(x, out, false)),
            _ => {}
        }
    }
    let mut produced = std::collections::BTreeSet::new();
    for lesson in ["box-four-corners", "box-stack"] {
        collect(
            &json(&["resolve", lesson, "--format", "json", "--log"]),
            &mut produced,
            false,
        );
    }
    let doc =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/resolve.md")).unwrap();
    let documented: std::collections::BTreeSet<String> = doc
        .lines()
        .filter(|l| l.starts_with("| `"))
        .flat_map(|l| {
            l.split(" | ")
                .next()
                .unwrap()
                .split('`')
                .skip(1)
                .step_by(2)
                .map(str::to_string)
                .collect::<Vec<_>>()
        })
        .collect();
    assert_eq!(produced, documented);
}

/// solves the contact alone.
#[test]
fn a_resolve_that_would_overflow_is_refused_not_printed_as_nan() {
    let text = r#"id = "compounds"
title = "A kinetic-direction contact that gains energy each iteration"

[[body]]
name = "a"
mass = 1e-2
shape = { sphere = 1e-2 }
position = [0e0, 0e0, 0e0]
orientation = [0e0, 0e0, 0e0, 3.157282506847742e0]
angular_velocity = [0e0, 0e0, 2.5262785208061715e42]

[[body]]
name = "b"
mass = 1e-2
shape = { cylinder = { radius = 5.9165870772058554e1, height = 1e-2 } }
position = [0e0, 0e0, 1.6348583195291289e44]
orientation = [-1.216850513646529e0, -3.708478557730917e-1, 3.656956475211908e-11, -2.116646867987548e0]

[[contact]]
bodies = ["a", "b"]
point = [-1e60, 0e0, 0e0]
normal = [-6.2365331714715764e32, 1e0, 0e0]
restitution = 0e0
static_friction = 1e60
friction_model = "kinetic-direction"
settings = { projection = "linear" }
"#;
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("resolve-compounds.toml");
    std::fs::write(&path, text).unwrap();
    let path = path.display().to_string();
    assert_eq!(run(&["solve", &path]).code, Some(0));
    for format in ["text", "json", "md"] {
        let r = run(&["resolve", &path, "--format", format]);
        assert_eq!(r.code, Some(1), "{format}: {}", r.stderr);
        assert!(r.stdout.is_empty(), "{format}: {}", r.stdout);
        assert!(
            r.stderr.contains(
                "error: compounds: resolving the contacts together overflows a 64-bit float: the kinetic energy after reaches NaN"
            ),
            "{}",
            r.stderr
        );
    }
}

#[test]
fn solve_and_resolve_share_one_after_table_with_units() {
    let header = |args: &[&str]| -> String {
        let r = run(args);
        assert_eq!(r.code, Some(0), "{args:?}: {}", r.stderr);
        r.stdout
            .lines()
            .find(|l| l.starts_with("| body |"))
            .unwrap_or_else(|| panic!("{args:?}: no After table"))
            .to_string()
    };
    let solve = header(&["solve", "lecture-2", "--format", "md"]);
    let resolve = header(&["resolve", "box-four-corners", "--format", "md"]);
    assert_eq!(solve, resolve);
    assert!(solve.contains("velocity (m/s)"), "{solve}");
}
