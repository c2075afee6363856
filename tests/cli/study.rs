//! `contact-lab study` through the binary: the `--no-timing` output held as
//! snapshots (a quick grid on two small scenes), the JSON and CSV contracts
//! of docs/study.md, the SVG as well-formed XML with one panel per scene and
//! a Pareto front, and bad input (unknown scene 66, not a scene 2, bad knob 2).

use crate::common;

use serde_json::Value as J;

use crate::common::cli::contact_lab;

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let out = contact_lab().args(args).output().expect("contact-lab runs");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The quick study of two small scenes, half a second each, no timing.
const QUICK: [&str; 7] = [
    "study",
    "ramp-stick",
    "cradle-over-time",
    "--quick",
    "--no-timing",
    "--seconds",
    "0.5",
];

fn quick(format: &str) -> String {
    let mut args = QUICK.to_vec();
    args.extend(["--format", format]);
    let (code, out, err) = run(&args);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.is_empty(), "no progress bar off a terminal: {err}");
    out
}

#[test]
fn no_timing_text_and_markdown_are_held_as_snapshots() {
    let text = quick("text");
    assert_eq!(text, quick("text"), "deterministic");
    common::snapshot_settings().bind(|| {
        insta::assert_snapshot!("study_quick_text", text);
        insta::assert_snapshot!("study_quick_md", quick("md"));
    });
}

#[test]
fn json_rows_carry_the_contract_and_mark_a_front() {
    let v: J = serde_json::from_str(&quick("json")).unwrap();
    assert_eq!(v["cost"], "work_per_second");
    let scenes = v["scenes"].as_array().unwrap();
    assert_eq!(scenes.len(), 2);
    for s in scenes {
        assert!(s["reference"].as_str().unwrap().contains("dt = 1/480"));
        let rows = s["rows"].as_array().unwrap();
        // default, 3 solvers (sequential warm-started too) × 3 budgets less the
        // default's own, f32, dt = 1/30.
        assert_eq!(rows.len(), 11, "{}", s["scene"]);
        for r in rows {
            for key in [
                "config",
                "max_penetration",
                "max_closing_velocity",
                "energy_gain",
                "drift",
                "error_vs_reference",
                "pareto",
                "contact_visits_per_step",
                "ccd_tests_per_step",
            ] {
                assert!(r.get(key).is_some(), "{key} in {r}");
            }
            assert!(r.get("microseconds_per_step").is_none(), "--no-timing");
            // The budget, the float type and every study knob of the table.
            let knobs = contact_lab::study::study_knobs().count();
            assert_eq!(r["config"].as_object().unwrap().len(), 2 + knobs);
        }
        assert!(rows.iter().any(|r| r["pareto"] == true));
    }
    // ramp-stick: the lecture's order creeps, sequential impulses stick.
    let ramp = &scenes[0]["rows"];
    let error = |solver: &str, budget: J| {
        ramp.as_array()
            .unwrap()
            .iter()
            .find(|r| r["config"]["solver"] == solver && r["config"]["budget"] == budget)
            .unwrap()["error_vs_reference"]
            .as_f64()
            .unwrap()
    };
    assert!(error("deepest-first", J::from(8)) > 0.05);
    assert!(error("sequential-impulse", J::from(8)) < 1e-3);
}

#[test]
fn csv_has_one_line_per_row_and_the_same_columns() {
    let csv = quick("csv");
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 1 + 22);
    let columns = lines[0].split(',').count();
    assert!(lines[0].starts_with("scene,knob,value,budget,precision,friction_model,"));
    assert!(!lines[0].contains("microseconds"));
    for l in &lines[1..] {
        assert_eq!(l.split(',').count(), columns, "{l}");
    }
}

#[test]
fn svg_is_well_formed_with_a_panel_per_scene_and_a_front() {
    let svg = quick("svg");
    let doc = roxmltree::Document::parse(&svg).expect("well-formed SVG");
    let texts: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
    assert!(texts.iter().any(|t| t.contains("ramp-stick")));
    assert!(texts.iter().any(|t| t.contains("cradle-over-time")));
    assert!(svg.contains("<polyline"), "the front is joined");
}

#[test]
fn a_user_grid_runs_its_cross_product() {
    let (code, out, err) = run(&[
        "study",
        "cradle-over-time",
        "--no-timing",
        "--seconds",
        "0.2",
        "--grid",
        "solver=deepest_first,sequential_impulse",
        "--grid",
        "budget=1,4",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let v: J = serde_json::from_str(&out).unwrap();
    let rows = v["scenes"][0]["rows"].as_array().unwrap();
    // The default and the four combinations.
    assert_eq!(rows.len(), 5);
    assert_eq!(rows[1]["value"], "solver=deepest_first, budget=1");
}

/// Continuous detection's work is in the deterministic cost: on
/// bullet-wall (no contact is ever resolved by the phases, so every row
/// makes 0 contact visits) each ccd row, every other knob as the default's
/// `ccd = "none"`, does more work than the default, by its time-of-collision
/// tests, and is not starred for free.
#[test]
fn ccd_rows_cost_their_time_of_collision_tests() {
    let (code, out, err) = run(&[
        "study",
        "bullet-wall",
        "--no-timing",
        "--grid",
        "ccd=none,bisection,conservative",
        "--format",
        "json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let v: J = serde_json::from_str(&out).unwrap();
    let rows = v["scenes"][0]["rows"].as_array().unwrap();
    let work = |r: &J| {
        r["contact_visits_per_step"].as_f64().unwrap() + r["ccd_tests_per_step"].as_f64().unwrap()
    };
    let none = &rows[0];
    assert_eq!(none["config"]["ccd"], "none");
    assert_eq!(none["ccd_tests_per_step"], 0.0);
    let without_ccd = |r: &J| {
        let mut c = r["config"].clone();
        c.as_object_mut().unwrap().remove("ccd");
        c
    };
    for method in ["bisection", "conservative"] {
        let r = rows
            .iter()
            .find(|r| r["config"]["ccd"] == method)
            .unwrap_or_else(|| panic!("a {method} row"));
        assert_eq!(without_ccd(r), without_ccd(none), "only ccd differs");
        assert!(r["ccd_tests_per_step"].as_f64().unwrap() > 0.0, "{r}");
        assert!(
            work(r) > work(none),
            "{method}: {} vs {}",
            work(r),
            work(none)
        );
    }
}

#[test]
fn bad_input_gets_a_clear_error_and_its_exit_code() {
    let (code, _, err) = run(&["study", "no-such-scene", "--no-timing"]);
    assert_eq!(code, Some(66), "{err}");
    let (code, _, err) = run(&["study", "lecture-2", "--no-timing"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("not a scene"), "{err}");
    let (code, _, err) = run(&["study", "ball-drop", "--grid", "budget=lots"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("budget=lots"), "{err}");
    let (code, _, err) = run(&["study", "ball-drop", "--grid", "colour=red"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("unknown knob 'colour'"), "{err}");
    let (code, _, err) = run(&["study", "ball-drop", "--seconds", "-1"]);
    assert_eq!(code, Some(2), "{err}");
}

/// The front is computed on the cost the chart plots, advise's work per
/// simulated second: on resting-box a smaller time step pays for its extra
/// steps (dt = 1/480 costs more than 1/120; per step it looked cheaper),
/// and no starred row is dominated by another row on (work per simulated
/// second, error), recomputed from the JSON.
#[test]
fn the_front_is_computed_on_work_per_simulated_second() {
    let (code, out, err) = run(&["study", "resting-box", "--no-timing", "--format", "json"]);
    assert_eq!(code, Some(0), "{err}");
    let v: J = serde_json::from_str(&out).unwrap();
    assert_eq!(v["cost"], "work_per_second");
    let scene = &v["scenes"][0];
    let rows = scene["rows"].as_array().unwrap();
    let seconds = scene["seconds"].as_f64().unwrap();
    let cost = |r: &J| r["work_per_second"].as_f64().unwrap();
    let error = |r: &J| r["error_vs_reference"].as_f64();
    // advise's cost: (visits + ccd tests + 1) per step × steps per second.
    for r in rows {
        let per_step = r["contact_visits_per_step"].as_f64().unwrap()
            + r["ccd_tests_per_step"].as_f64().unwrap()
            + 1.0;
        let steps = r["steps"].as_f64().unwrap();
        let expected = per_step * steps / seconds;
        assert!((cost(r) - expected).abs() <= 1e-9 * expected, "{r}");
    }
    let dt = |label: &str| {
        rows.iter()
            .find(|r| r["knob"] == "dt" && r["value"] == label)
            .unwrap_or_else(|| panic!("a dt = {label} row"))
    };
    assert!(
        cost(dt("1/480")) > cost(dt("1/120")),
        "{} vs {}",
        cost(dt("1/480")),
        cost(dt("1/120"))
    );
    let point = |r: &J| {
        let e = error(r)?;
        (r["failure"].is_null() && e.is_finite()).then_some((cost(r), e))
    };
    let mut starred = 0;
    for (i, a) in rows.iter().enumerate() {
        if a["pareto"] != true {
            continue;
        }
        starred += 1;
        let (ca, ea) = point(a).expect("a starred row has numbers");
        for (j, b) in rows.iter().enumerate() {
            let Some((cb, eb)) = point(b) else { continue };
            let dominated =
                j != i && ((cb < ca && eb <= ea) || (cb <= ca && eb < ea - (1e-6 * ea).max(1e-12)));
            assert!(!dominated, "starred {a}\n is dominated by {b}");
        }
    }
    assert!(starred > 0);
}

/// The chart on a slide: the same rows as the JSON, at most eight legend
/// entries (one colour per family), one marker per value within a family,
/// and the front a staircase (every segment level or upright) through the
/// starred rows.
#[test]
fn the_chart_has_a_legend_of_families_and_a_staircase_front() {
    use contact_lab::render::study::svg;
    let o = contact_lab::study::sweep::Options {
        timed: false,
        repeats: 1,
        quick: false,
        grid: Vec::new(),
    };
    let lesson = contact_lab::lesson::Lesson::load(std::ffi::OsStr::new("stack-5")).unwrap();
    let spec = contact_lab::study::sweep::SceneSpec {
        lesson,
        seconds: 0.25,
        reference_solver: contact_lab::physics::Solver::SequentialImpulse,
    };
    let st = contact_lab::study::sweep::study(&[spec], &o, &mut |_, _| {});
    let rows = &st.scenes[0].rows;
    let families = svg::families(rows);
    assert!(families.len() <= svg::MAX_FAMILIES, "{families:?}");
    let colours: std::collections::HashSet<_> = families.iter().map(|f| f.colour).collect();
    assert_eq!(colours.len(), families.len(), "one colour per family");
    let mut seen: Vec<usize> = families
        .iter()
        .flat_map(|f| f.members.iter().map(|m| m.0))
        .collect();
    seen.sort();
    assert_eq!(seen, (0..rows.len()).collect::<Vec<_>>(), "every row once");
    for f in &families {
        let marks: std::collections::HashSet<_> =
            f.members.iter().map(|m| format!("{:?}", m.1)).collect();
        assert_eq!(marks.len(), f.members.len(), "one marker per value: {f:?}");
    }
    let doc = svg::render(&st);
    assert!(doc.contains(svg::X_LABEL), "the x axis is the front's cost");
    let front = doc
        .split("<polyline points=\"")
        .nth(1)
        .expect("the front is drawn")
        .split('"')
        .next()
        .unwrap();
    let points: Vec<(f64, f64)> = front
        .split(' ')
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect();
    for w in points.windows(2) {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        assert!(x0 == x1 || y0 == y1, "a staircase: {w:?}");
        assert!(
            x1 >= x0 && y1 >= y0,
            "cheaper to dearer, error falling: {w:?}"
        );
    }
}

/// `--verdicts` runs its own scenes: scenes, `--grid` and `--seconds` are
/// refused (2) before anything runs, and so are the formats it does not print.
#[test]
fn verdicts_refuse_what_they_do_not_take() {
    for args in [
        &["study", "--verdicts", "stack-5"][..],
        &["study", "--verdicts", "--grid", "budget=1,2"],
        &["study", "--verdicts", "--seconds", "1"],
        &["study", "--verdicts", "--format", "csv"],
        &["study", "--verdicts", "--format", "md"],
        &["study", "--verdicts", "--format", "html"],
    ] {
        let (code, out, err) = run(args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}");
        assert!(err.contains("--verdicts"), "{args:?}: {err}");
    }
}
