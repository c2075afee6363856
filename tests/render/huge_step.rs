//! A huge step's recording (issue 23): past the row budget the iterations
//! are all kept (contact taken, value, moves or impulse) but the rows they
//! changed only at every K-th iteration, and the text, the JSON and the
//! resolver screen's tables say so. A pile of 32 coincident spheres on a
//! floor (528 contacts) records just over the budget.

use contact_lab::lesson::Lesson;
use contact_lab::physics::resolver::Phase;
use contact_lab::session::Player;
use contact_lab::trace::resolver::ROW_BUDGET;
use serde_json::Value as J;

use crate::common::cli::{run, Run};

/// A scene of `n` spheres all at the same place on a floor.
fn pile(n: usize) -> std::path::PathBuf {
    crate::common::pile::coincident("huge-step", n)
}

fn trace_step(path: &std::path::Path, json: bool) -> Run {
    let path = path.to_str().unwrap();
    let mut args = vec!["simulate", path, "--trace-step", "1"];
    if json {
        args.extend(["--format", "json"]);
    }
    run(&args)
}

#[test]
fn a_huge_steps_json_says_it_elided_the_rows_and_counts_them() {
    let run = trace_step(&pile(32), true);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let j: J = serde_json::from_str(&run.stdout).unwrap();
    let every = j["elided"]["updated_every"].as_u64().expect("elided");
    assert_eq!(j["elided"]["row_budget"].as_u64(), Some(ROW_BUDGET as u64));
    assert!(every >= 2 && every.is_power_of_two(), "{every}");
    let log = j["position"]["log"].as_array().unwrap();
    assert_eq!(
        log.len() as u64,
        j["position"]["iterations_used"].as_u64().unwrap(),
        "every iteration is listed"
    );
    let mut kept_rows = 0;
    for e in log {
        let i = e["iteration"].as_u64().unwrap();
        if i % every == 0 {
            let rows = e["updated"].as_array().expect("kept rows");
            assert!(e.get("changed").is_none());
            kept_rows += rows.len();
        } else {
            assert!(e["updated"].is_null(), "iteration {i}: {}", e["updated"]);
            // Each sphere touches the floor and the 31 others: 62 rows.
            assert!(e["changed"].as_u64().unwrap() > 0, "iteration {i}");
        }
    }
    assert!(kept_rows > 0 && kept_rows <= ROW_BUDGET, "{kept_rows}");
}

#[test]
fn a_huge_steps_text_says_it_elided_the_rows() {
    let run = trace_step(&pile(32), false);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let text = run.stdout;
    assert!(text.contains("Elided: a huge step."), "{}", &text[..2000]);
    assert!(text.contains("(rows elided)"));
    assert!(text.contains("Contacts before") && text.contains("Contacts after"));
    // Iteration 0 keeps its rows ("from → to (worse)"), iteration 1 counts them.
    let at = |tag: &str| text.find(tag).unwrap_or_else(|| panic!("{tag}"));
    let (p0, p1, p2) = (at("\n   p0 "), at("\n   p1 "), at("\n   p2 "));
    assert!(text[p0..p1].contains("(worse)"), "{}", &text[p0..p1]);
    assert!(!text[p0..p1].contains("rows elided"));
    assert!(
        text[p1..p2].contains("for the worse (rows elided)"),
        "{}",
        &text[p1..p2]
    );
}

#[test]
fn a_small_steps_json_has_no_elided_field() {
    let run = run(&[
        "simulate",
        "stack-5",
        "--trace-step",
        "75",
        "--format",
        "json",
    ]);
    assert_eq!(run.code, Some(0));
    let j: J = serde_json::from_str(&run.stdout).unwrap();
    assert!(j.get("elided").is_none());
}

#[test]
fn a_huge_steps_tables_are_whole_only_at_each_phases_ends() {
    let lesson = Lesson::load(pile(32).as_os_str()).unwrap();
    let mut p = Player::new(&lesson).unwrap();
    assert!(p.reach(1));
    let s = p.record(1).expect("step 1 records");
    let e = s.resolver.elision.expect("elided");
    let np = s.resolver.position.iterations_used;
    let nv = s.resolver.velocity.iterations_used;
    assert_eq!(s.tables.len(), np + nv + 2);
    let contacts = s.world.contacts.len();
    for (t, table) in s.tables.iter().enumerate() {
        let end = t == 0 || t == np || t == np + 1 || t == np + nv + 1;
        assert_eq!(table.elided, !end, "stop {t}");
        assert_eq!(table.penetration.len(), if end { contacts } else { 0 });
    }
    let last = s.tables.last().unwrap();
    for (k, row) in s.resolver.contacts_after.iter().enumerate() {
        assert_eq!(last.penetration[k], row.penetration);
        assert_eq!(last.desired[k], row.desired);
    }
    assert_eq!(s.tables[np + 1].stop.phase, Phase::Velocity);
    // Stop 2 follows iteration 1 (elided): only the taken contact changed
    // is kept; stop 1 follows iteration 0 (kept): all its rows.
    let it0 = &s.resolver.position.log[0];
    assert_eq!(s.tables[1].changed.len(), 1 + it0.updated.len());
    assert_eq!(it0.updated.len(), it0.changed);
    let it1 = &s.resolver.position.log[1];
    assert!(it1.elided && it1.updated.is_empty() && it1.changed > 0);
    assert_eq!(s.tables[2].changed.len(), 1);
    // The picture at an elided stop shows the bodies of the last kept one.
    assert_eq!(s.bodies_stop(1), 0);
    assert_eq!(s.bodies_stop(e.every), e.every);
    assert_eq!(s.penetration_at(2, it1.contact), it1.own_after);
}
