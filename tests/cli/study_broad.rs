//! `study --broad-phase`: deterministic without timing, the text table's
//! numbers are the JSON's, every method keeps the same pairs, and the
//! verdict names the method with the fewest tests; bad counts are refused.

use crate::common::cli::run;

#[test]
fn the_broad_phase_study_prints_the_counts_its_json_holds() {
    let args = [
        "study",
        "--broad-phase",
        "--no-timing",
        "--bodies",
        "10,200",
    ];
    let json = run(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(json.code, Some(0), "{}", json.stderr);
    let again = run(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(json.stdout, again.stdout, "deterministic without timing");
    let text = run(&[&args[..], &["--width", "0"]].concat());
    assert_eq!(text.code, Some(0), "{}", text.stderr);
    let doc: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    let cases = doc["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 2);
    for case in cases {
        for point in case["points"].as_array().unwrap() {
            let bodies = point["bodies"].as_u64().unwrap();
            assert_eq!(point["all_pairs"].as_u64(), Some(bodies * (bodies - 1) / 2));
            let methods = point["methods"].as_array().unwrap();
            let names: Vec<&str> = methods
                .iter()
                .map(|m| m["method"].as_str().unwrap())
                .collect();
            assert_eq!(names, ["sweep", "grid", "bvh"]);
            let kept = &methods[0]["kept"];
            let fewest = methods
                .iter()
                .min_by_key(|m| m["tests"].as_u64().unwrap())
                .unwrap();
            assert_eq!(point["fewest_tests"], fewest["method"]);
            for m in methods {
                assert_eq!(&m["kept"], kept, "the same pairs under every method");
                assert!(m["microseconds_per_frame"].is_null());
                // The text's row: bodies, method, tests, visited, kept, loose.
                let row = format!(
                    "{} {} {} {} {} {}",
                    bodies,
                    m["method"].as_str().unwrap(),
                    m["tests"],
                    m["visited"],
                    m["kept"],
                    m["loose"]
                );
                let found = text
                    .stdout
                    .lines()
                    .any(|l| l.split_whitespace().collect::<Vec<_>>().join(" ") == row);
                assert!(found, "{row:?} not in\n{}", text.stdout);
            }
            let verdict = format!(
                "{bodies} bodies: fewest tests {} ({} of all-against-all's {})",
                fewest["method"].as_str().unwrap(),
                fewest["tests"],
                point["all_pairs"]
            );
            assert!(text.stdout.contains(&verdict), "{verdict:?}");
        }
    }
    let svg = run(&[&args[..], &["--format", "svg"]].concat());
    assert!(svg.stdout.starts_with("<svg") && svg.stdout.contains("box tests per frame"));
    let bad = run(&["study", "--broad-phase", "--bodies", "1"]);
    assert_eq!(bad.code, Some(2), "{}", bad.stderr);
    assert!(bad.stderr.contains("--bodies"), "{}", bad.stderr);
}
