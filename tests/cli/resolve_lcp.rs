//! `resolve --solver lcp` and `resolve --compare A,B` through the binary:
//! the JSON `lcp` object (method, restitution, pivots, impulses), the
//! bodies after, the comparison side by side, a bad pair refused (2).

use serde_json::Value as J;

use crate::common::cli::run;

fn json(args: &[&str]) -> J {
    let r = run(args);
    assert_eq!(r.code, Some(0), "{args:?}: {}", r.stderr);
    serde_json::from_str(&r.stdout).expect("JSON")
}

#[test]
fn lcp_json_has_the_pivots_and_the_simultaneous_answer() {
    let v = json(&[
        "resolve",
        "impact-row-3",
        "--solver",
        "lcp",
        "--format",
        "json",
    ]);
    let lcp = &v["lcp"];
    assert_eq!(lcp["method"], "lemke");
    assert_eq!(lcp["restitution"], "newton");
    let pivots = lcp["pivots"].as_array().unwrap();
    assert_eq!(pivots.len(), 3);
    assert_eq!(pivots[0]["entering"], "z0");
    assert!(pivots
        .iter()
        .all(|p| p["ratio"].is_number() && p["leaving"].is_string()));
    let ball0 = v["after"]["ball0"]["velocity"][0].as_f64().unwrap();
    assert!((ball0 + 1.0 / 3.0).abs() < 1e-12, "{ball0}");
    let text = run(&["resolve", "impact-row-3", "--solver", "lcp"]).stdout;
    assert!(
        text.contains("pivot 1 (newton): lambda0 enters, w1 leaves"),
        "{text}"
    );
}

#[test]
fn compare_puts_the_sequence_beside_the_simultaneous_solve() {
    let v = json(&[
        "resolve",
        "impact-row-3",
        "--compare",
        "deepest-first,lcp",
        "--format",
        "json",
    ]);
    let both = v["compare"].as_array().unwrap();
    assert_eq!(both[0]["solver"], "deepest-first");
    assert_eq!(both[1]["solver"], "lcp");
    assert_eq!(both[0]["after"]["ball2"]["velocity"][0], 1.0);
    assert!(both[1]["lcp"].is_object() && both[0].get("lcp").is_none());
    let r = run(&["resolve", "impact-row-3", "--compare", "deepest-first,nope"]);
    assert_eq!(r.code, Some(2));
    assert!(r.stderr.contains("unknown solver 'nope'"), "{}", r.stderr);
}

/// Every format of `resolve --solver lcp` shows the simultaneous solve
/// (A, b and each pivot), not only text and JSON.
#[test]
fn every_format_shows_the_pivots() {
    for format in ["md", "html"] {
        let r = run(&[
            "resolve",
            "impact-row-3",
            "--solver",
            "lcp",
            "--format",
            format,
        ]);
        assert_eq!(r.code, Some(0), "{format}: {}", r.stderr);
        assert!(
            r.stdout
                .contains("pivot 1 (newton): lambda0 enters, w1 leaves"),
            "{format}: {}",
            r.stdout
        );
        assert!(r.stdout.contains("The simultaneous solve"), "{format}");
    }
}
