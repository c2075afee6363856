//! One time step's resolution recorded on request: `simulate --trace-step N`
//! (text and JSON, the shape of `resolve`'s trace), the player the TUI reads
//! (a recorded step agrees with the step as the run took it, from any
//! checkpoint), and the stop-by-stop tables of the resolver screen.

use assert_cmd::Command;
use contact_lab::lesson::Lesson;
use contact_lab::physics::resolver::Phase;
use contact_lab::session::{Player, CHECKPOINT};
use contact_lab::trace::step::StepTrace;
use serde_json::Value as J;

fn contact_lab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args(args)
        .output()
        .expect("contact-lab runs")
}

#[test]
fn trace_step_json_has_resolves_shape_and_the_steps_iterations() {
    let out = contact_lab(&[
        "simulate",
        "stack-5",
        "--trace-step",
        "75",
        "--format",
        "json",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let j: J = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "lesson", "contacts", "position", "velocity", "seconds", "after",
    ] {
        assert!(j.get(key).is_some(), "no {key}");
    }
    assert_eq!(j["lesson"], "stack-5");
    // The step as the run took it: the same counts as simulate's JSON row.
    let run = contact_lab(&["simulate", "stack-5", "--steps", "75", "--format", "json"]);
    let r: J = serde_json::from_slice(&run.stdout).unwrap();
    let row = r["steps"].as_array().unwrap().last().unwrap().clone();
    assert_eq!(row["step"], 75);
    assert_eq!(j["contacts"], row["contacts"]);
    assert_eq!(j["velocity"]["iterations_used"], row["velocity_iterations"]);
    assert_eq!(j["position"]["iterations_used"], row["position_iterations"]);
    let log = j["velocity"]["log"]
        .as_array()
        .expect("the log is always there");
    assert_eq!(
        log.len() as u64,
        row["velocity_iterations"].as_u64().unwrap()
    );
}

#[test]
fn trace_step_text_names_the_step_and_refuses_steps_past_the_end() {
    let out = contact_lab(&[
        "simulate",
        "ball-drop",
        "--trace-step",
        "460",
        "--steps",
        "500",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("Step 460 (t = 0.46 s)"), "{text}");
    assert!(text.contains("Velocity phase"), "{text}");
    let out = contact_lab(&[
        "simulate",
        "ball-drop",
        "--steps",
        "10",
        "--trace-step",
        "11",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("--trace-step 11: the run has 10 step(s)"),
        "{err}"
    );
    let out = contact_lab(&["simulate", "lecture-2", "--trace-step", "1"]);
    assert_eq!(out.status.code(), Some(2));
    let out = contact_lab(&[
        "simulate",
        "stack-5",
        "--trace-step",
        "3",
        "--format",
        "svg",
    ]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn a_recorded_step_agrees_with_the_run_from_any_checkpoint() {
    let lesson = Lesson::load("stack-5").unwrap();
    let mut p = Player::new(&lesson).unwrap();
    assert!(p.reach(2 * CHECKPOINT + 5));
    for step in [1, CHECKPOINT, CHECKPOINT + 1, 2 * CHECKPOINT + 5] {
        let s = p.record(step).expect("a computed step records");
        let f = &p.run.frames[step as usize];
        assert_eq!(s.step, step);
        assert_eq!(s.world.contacts.len(), f.contacts, "step {step}");
        assert_eq!(s.resolver.position.iterations_used, f.position_iterations);
        assert_eq!(s.resolver.velocity.iterations_used, f.velocity_iterations);
        // The bodies after both phases are the frame's velocities (positions
        // are integrated after the resolver).
        let stops = s.tables.len();
        let after = s.bodies_at(stops - 1);
        for (b, fb) in after.iter().zip(&f.bodies) {
            if b.movable {
                assert_eq!(b.velocity, fb.velocity, "step {step} {}", b.name);
            }
        }
    }
    assert!(p.record(0).is_none());
    assert!(p.record(p.computed() + 1).is_none());
}

#[test]
fn tables_follow_the_log_stop_by_stop() {
    let lesson = Lesson::load("box-four-corners").unwrap();
    let s = StepTrace::of_lesson(&lesson);
    let (np, nv) = (
        s.resolver.position.iterations_used,
        s.resolver.velocity.iterations_used,
    );
    assert!(np > 0 && nv > 0);
    assert_eq!(s.tables.len(), np + nv + 2);
    assert_eq!(s.velocity_start(), np + 1);
    let first = &s.tables[0];
    assert_eq!(first.stop.phase, Phase::Position);
    assert_eq!(first.next, Some(s.resolver.position.log[0].contact));
    assert!(first.changed.is_empty());
    // After the first iteration: the taken contact holds its value after.
    let it = &s.resolver.position.log[0];
    let second = &s.tables[1];
    assert_eq!(second.penetration[it.contact], it.own_after);
    assert_eq!(second.changed[0], (it.contact, it.value, it.own_after));
    for u in &it.updated {
        assert_eq!(second.penetration[u.contact], u.to);
    }
    // The end of each phase agrees with the resolver's contacts after.
    let last = s.tables.last().unwrap();
    assert_eq!(last.next, None);
    for (k, row) in s.resolver.contacts_after.iter().enumerate() {
        assert_eq!(last.penetration[k], row.penetration);
        assert_eq!(last.desired[k], row.desired);
    }
    // The lesson at a stop: bodies as that stop finds them.
    let t = 3.min(np);
    let at = s.lesson_at(&lesson, t);
    let views = s.bodies_at(t);
    for (def, v) in at.bodies.iter().zip(&views) {
        assert_eq!(<[f64; 3]>::from(def.position), v.position);
    }
    assert_eq!(at.contacts.len(), lesson.contacts.len());
}

#[test]
fn a_warm_started_step_is_recorded_as_the_run_took_it() {
    // Sequential impulses start from last step's impulses: the recording
    // must start from the same warm-started resolver, not a fresh one.
    let flags = [
        "--solver",
        "sequential_impulse",
        "--warm-start",
        "--format",
        "json",
    ];
    let mut args = vec!["simulate", "stack-5", "--trace-step", "40"];
    args.extend(flags);
    let out = contact_lab(&args);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let j: J = serde_json::from_slice(&out.stdout).unwrap();
    let mut args = vec!["simulate", "stack-5", "--steps", "40"];
    args.extend(flags);
    let r: J = serde_json::from_slice(&contact_lab(&args).stdout).unwrap();
    let row = r["steps"].as_array().unwrap().last().unwrap().clone();
    assert_eq!(row["step"], 40);
    // The bodies after both phases are the run's velocities after step 40.
    for (name, body) in row["bodies"].as_object().unwrap() {
        assert_eq!(
            j["after"][name]["velocity"], body["velocity"],
            "{name}: the recorded resolution ends where the run's did"
        );
    }
}

/// A step without contacts (the ball in flight) says so: no `-inf` for the
/// deepest penetration of nothing, no "at contact 0" of no contact.
#[test]
fn a_step_without_contacts_says_there_are_none() {
    let out = contact_lab(&["simulate", "ball-drop", "--trace-step", "5"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        text.matches("No contacts: nothing to resolve.").count(),
        2,
        "{text}"
    );
    assert!(text.contains("penetration left: no contacts"), "{text}");
    assert!(!text.contains("inf"), "{text}");
    let out = contact_lab(&[
        "simulate",
        "ball-drop",
        "--trace-step",
        "5",
        "--format",
        "json",
    ]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["position"]["max_penetration_before"], 0.0);
    assert_eq!(json["velocity"]["max_desired_after"], 0.0);
}

/// `resolve` on a scene that writes no contact points to `--trace-step`
/// (exit 2, nothing on stdout) rather than resolving nothing.
#[test]
fn resolve_of_a_scene_without_contacts_points_to_trace_step() {
    let out = contact_lab(&["resolve", "stack-5"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("simulate stack-5 --trace-step N"), "{err}");
}
