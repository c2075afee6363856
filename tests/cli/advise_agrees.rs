//! advise's output agrees with itself and loads: its snippet, merged into
//! the scene by the rule it prints (a key the scene already sets is
//! replaced), loads on every embedded scene and meets the target (a short
//! advice here; the measure layer's advise_every_scene runs every scene's
//! full one through the same merge); a knob it says the scene does not need is named with the
//! value the snippet sets; a scene whose own run blows up is said first;
//! the time step is shown as a fraction with its unit.

use crate::common::advise::{check, lesson, pasted};
use crate::common::cli::contact_lab;
use contact_lab::lesson::embedded;
use contact_lab::physics::Solver;
use contact_lab::study::advise::{advise, dimensions, run_of, settings_snippet, snippet, Per};
use contact_lab::study::{grid, run};

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = contact_lab().args(args).output().expect("contact-lab runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Every embedded scene: the snippet of its own configuration over every
/// searched dimension, merged key for key into the scene's file by the
/// printed rule, loads and is that configuration (fast: no search; the
/// measure layer's advise_every_scene merges each scene's searched advice,
/// runs it and checks the target).
#[test]
fn the_snippet_merged_into_every_embedded_scene_loads() {
    for id in embedded::scene_ids() {
        let l = lesson(id);
        let Some((_, solver)) = run_of(&l) else {
            continue;
        };
        let default = grid::default_config(&l).unwrap();
        let reference = grid::reference(&default, solver);
        let (dims, _) = dimensions(&default, &reference, grid::features(&l));
        let names: Vec<&str> = dims.iter().map(|d| d.name).collect();
        for c in [default, reference] {
            let p = pasted(id, &snippet(&c, &names, &l.spellings));
            let mut back = grid::default_config(&p).unwrap();
            back.precision = c.precision;
            assert_eq!(run::params(&back), run::params(&c), "{id}");
        }
    }
}

/// A short advice on ball-drop, merged, loaded, run: it meets its target
/// (`common::advise::check`).
#[test]
fn a_short_advice_merged_and_run_meets_its_target() {
    let l = lesson("ball-drop");
    let a = advise(&l, 0.2, Solver::SequentialImpulse, 0.05, Per::Run).unwrap();
    check(&a, Solver::SequentialImpulse, false);
}

/// ball-drop spells sleep `enabled` in `[sleep]`: the snippet says
/// `enabled` too (a `sleep = …` beside the scene's `enabled = …` set the
/// knob twice and the scene was refused with exit 65).
#[test]
fn the_snippet_spells_each_knob_as_the_scene_does() {
    let l = lesson("ball-drop");
    assert!(l
        .spellings
        .iter()
        .any(|(_, knob, key)| *knob == "sleep" && key == "enabled"));
    let a = advise(
        &l,
        0.2,
        contact_lab::physics::Solver::SequentialImpulse,
        0.01,
        Per::Run,
    )
    .unwrap();
    let snippet = settings_snippet(&a);
    let sleep = snippet.split("[sleep]").nth(1).expect("a [sleep] table");
    assert!(sleep.contains("\nenabled = "), "{snippet}");
    assert!(!snippet.contains("\nsleep = "), "{snippet}");
}

/// ramp-stick: what the scene does not need is named with the value the
/// snippet sets (relaxation was listed as not needed while the snippet set
/// `relaxation = 0.5`); the time step is a fraction with its unit, the
/// snippet's decimal named beside it.
#[test]
fn what_the_scene_does_not_need_is_the_value_the_snippet_sets() {
    let (code, out, err) = run(&[
        "advise",
        "ramp-stick",
        "--error",
        "0.01",
        "--seconds",
        "0.2",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let fine = out
        .split("Fine at their cheapest value, which the snippet sets")
        .nth(1)
        .expect("the section")
        .lines()
        .nth(1)
        .unwrap()
        .trim()
        .to_string();
    for item in fine.split(", ") {
        let (knob, value) = item.split_once(" = ").unwrap_or_else(|| panic!("{item}"));
        if knob == "precision" {
            continue; // a comment in the snippet: a lesson runs in f64
        }
        let value = value.trim_end_matches(" s");
        // The keys the snippet may write it under: the budget as
        // visits_per_contact, a knob under an old name the scene uses.
        let keys: Vec<&str> = match knob {
            "budget" => vec!["visits_per_contact"],
            _ => {
                let k = contact_lab::knobs::find(knob).unwrap();
                std::iter::once(k.name)
                    .chain(k.old_names.iter().copied())
                    .collect()
            }
        };
        // The snippet's lines, indented four spaces, quotes dropped.
        assert!(
            out.lines().any(|l| {
                let Some(l) = l.strip_prefix("    ") else {
                    return false;
                };
                let l = l.replace('"', "");
                keys.iter().any(|k| l.starts_with(&format!("{k} = ")))
                    && (l.contains(&format!("= {value}")) || l.contains(&format!("# {value} s")))
            }),
            "{knob} = {value} is not what the snippet sets:\n{out}"
        );
    }
    // The snippet writes the decimal the loader reads; the prose the fraction.
    for l in out.lines().filter(|l| !l.starts_with("    ")) {
        assert!(!l.contains("3333333"), "dt through the formatter: {l}");
    }
}

/// A scene whose own run blows up (velocity-scaling friction with μ_d =
/// 2.2): advise still answers (exit 0) but says first that the scene as
/// written blows up and what the advice changes.
#[test]
fn a_scene_whose_own_run_blows_up_is_said_up_front() {
    let (code, out, err) = run(&[
        "advise",
        "tests/truth/runaway-friction.toml",
        "--error",
        "0.01",
        "--seconds",
        "0.1",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.starts_with("Warning: the scene's own run"), "{out}");
    assert!(
        out.lines().next().unwrap().contains("friction_model"),
        "{out}"
    );
    assert!(err.is_empty(), "no progress off a terminal: {err}");
}
