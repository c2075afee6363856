//! `check` holds the simultaneous-impact lessons' closed forms (issue 43):
//! `[[printed]]` entries on `stage = "resolver"` (a body's velocity after
//! the contacts are resolved together, under the lesson's solver or one
//! named) and `stage = "lcp"` (the simultaneous impulse at a contact) agree;
//! a wrong one is a new disagreement (exit 1); a bad entry is refused at
//! load with its file:line:column (exit 65).

use crate::common::cli::run;

const LESSONS: [&str; 5] = [
    "impact-row-3",
    "impact-row-5",
    "impact-row-poisson",
    "impact-stack-r01",
    "impact-stack-r05",
];

#[test]
fn every_closed_form_agrees() {
    let mut args = vec!["check"];
    args.extend(LESSONS);
    let r = run(&args);
    assert_eq!(r.code, Some(0), "{}\n{}", r.stdout, r.stderr);
    assert!(!r.stderr.contains("warning"), "{}", r.stderr);
    let text = r.stdout.replace('\n', " ");
    let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
    for row in [
        "✓ v(ball0)[0] (after the resolver, lcp): printed -0.333333, computed -0.333333",
        "✓ v(ball2)[0] (after the resolver, deepest-first): printed 1.000000, computed 1",
        "✓ λ (simultaneous impact, lcp, contact 0): printed 1.333333",
        "✓ λ (simultaneous impact, lcp, contact 1): printed 0.666667",
        "✓ v(ball0)[0] (after the resolver, lcp): printed -0.600000, computed -0.6",
        "✓ v(ball0)[0] (after the resolver, lcp): printed -0.200000, computed -0.2",
        "✓ v(top)[1] (after the resolver, deepest-first): printed 2.636364, computed 2.63636",
        "✓ v(top)[1] (after the resolver, deepest-first): printed 1.666667, computed 1.66667",
    ] {
        assert!(text.contains(row), "no row {row:?} in:\n{}", r.stdout);
    }
    assert!(
        text.contains("5 lesson(s), 29 printed numbers: 29 agree, 0 known errata."),
        "{}",
        r.stdout
    );
    let json = run(&["check", "impact-row-3", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    let items = v["items"].as_array().unwrap();
    assert_eq!(items.len(), 8);
    assert!(items.iter().all(|i| i["status"] == "agrees"), "{v}");
    assert_eq!(items[0]["stage"], "resolver");
    assert_eq!(items[0]["scope"], "after the resolver, lcp");
}

/// impact-row-3 with its printed entries swapped for `printed`.
fn row_3_with(name: &str, printed: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string("lessons/impact-row-3.toml").unwrap();
    let body = text.split("\n[[printed]]").next().unwrap();
    let dir = crate::common::scratch(name);
    let path = dir.join("row.toml");
    std::fs::write(&path, format!("{body}\n{printed}")).unwrap();
    path
}

#[test]
fn a_wrong_closed_form_is_a_new_disagreement() {
    // The sequence's answer printed as the simultaneous one: ball0 at 0, not -v/3.
    let path = row_3_with(
        "check-resolved-wrong",
        "[[printed]]\nstage = \"resolver\"\nbody = \"ball0\"\nvalue = \"velocity\"\ncomponent = 0\nprinted = \"0.000000\"\nwhere = \"a slide\"\n",
    );
    let r = run(&["check", path.to_str().unwrap()]);
    assert_eq!(r.code, Some(1), "{}\n{}", r.stdout, r.stderr);
    assert!(r.stdout.contains("NEW DISAGREEMENT"), "{}", r.stdout);
    assert!(r.stdout.contains("computed  -0.333333"), "{}", r.stdout);
    // The same number under the sequence agrees.
    let path = row_3_with(
        "check-resolved-sequence",
        "[[printed]]\nstage = \"resolver\"\nsolver = \"deepest-first\"\nbody = \"ball0\"\nvalue = \"velocity\"\ncomponent = 0\nprinted = \"0.000000\"\nwhere = \"a slide\"\n",
    );
    let r = run(&["check", path.to_str().unwrap()]);
    assert_eq!(r.code, Some(0), "{}\n{}", r.stdout, r.stderr);
    // A wrong impulse too.
    let path = row_3_with(
        "check-resolved-impulse",
        "[[printed]]\nstage = \"lcp\"\ncontact = 1\nvalue = \"impulse\"\nprinted = \"1.333333\"\nwhere = \"a slide\"\n",
    );
    let r = run(&["check", path.to_str().unwrap()]);
    assert_eq!(r.code, Some(1), "{}\n{}", r.stdout, r.stderr);
    assert!(r.stdout.contains("computed  0.666667"), "{}", r.stdout);
}

/// `path:LINE:COLUMN` of the first `needle` in the file at `path`.
fn at(path: &std::path::Path, needle: &str) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let (n, line) = text
        .lines()
        .enumerate()
        .filter(|(_, l)| l.contains(needle))
        .last()
        .unwrap();
    format!("row.toml:{}:{}", n + 1, line.find(needle).unwrap() + 1)
}

#[test]
fn a_bad_resolved_entry_is_refused_where_it_stands() {
    let head = "[[printed]]\nstage = \"resolver\"\n";
    let tail = "value = \"velocity\"\ncomponent = 0\nprinted = 1.0\nwhere = \"a slide\"\n";
    for (name, entry, needle, says) in [
        (
            "no-body",
            format!("{head}body = \"ball9\"\n{tail}"),
            "\"ball9\"",
            "no body of that name",
        ),
        (
            "stepper",
            format!("{head}solver = \"xpbd\"\nbody = \"ball0\"\n{tail}"),
            "\"xpbd\"",
            "a time stepper",
        ),
        (
            "missing-body",
            format!("{head}{tail}"),
            "\"resolver\"",
            "needs `body",
        ),
        (
            "bad-value",
            "[[printed]]\nstage = \"lcp\"\nvalue = \"impulses\"\nprinted = 1.0\nwhere = \"a slide\"\n".to_string(),
            "\"impulses\"",
            "no value \"impulses\"",
        ),
    ] {
        let path = row_3_with(&format!("check-resolved-{name}"), &entry);
        let r = run(&["check", path.to_str().unwrap()]);
        assert_eq!(r.code, Some(65), "{name}: {}", r.stderr);
        assert!(r.stderr.contains(says), "{name}: {}", r.stderr);
        let where_ = at(&path, needle);
        assert!(r.stderr.contains(&where_), "{name}: {where_} in {}", r.stderr);
    }
}
