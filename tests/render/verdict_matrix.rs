//! `study --verdicts`' matrix on the reduced sizes: the same on one core and
//! on two, every solver of the knob's list a column, the JSON contract
//! (docs/study.md, the guide's study contract), each text and SVG cell the
//! verdict's own figure, the criteria quoted in docs/study.md, Ctrl-C before
//! the start, and the friction ramp against its closed form.

use std::sync::atomic::AtomicBool;
use std::sync::OnceLock;

use contact_lab::format::Fmt;
use contact_lab::knobs::Choice;
use contact_lab::physics::Solver;
use contact_lab::render::study::verdicts as render;
use contact_lab::study::verdicts::criteria::{ramp_boxes, G, SCENES};
use contact_lab::study::verdicts::record;
use contact_lab::study::verdicts::scenes::{RAMP_ANGLE, RAMP_BOX_FRICTION, RAMP_FRICTION};
use contact_lab::study::verdicts::{self, columns, Matrix, Size};

/// The reduced matrix on two threads, run once for the binary.
fn matrix() -> &'static Matrix {
    static M: OnceLock<Matrix> = OnceLock::new();
    M.get_or_init(|| verdicts::run(Size::Reduced, 2, &AtomicBool::new(false), &|_, _, _| {}))
}

#[test]
fn one_core_gives_the_matrix_of_two() {
    let one = verdicts::run(Size::Reduced, 1, &AtomicBool::new(false), &|_, _, _| {});
    assert_eq!(&one, matrix());
    assert_eq!(one.not_run, 0);
}

#[test]
fn every_solver_of_the_knob_is_a_column() {
    let labels: Vec<String> = columns().iter().map(|c| c.label()).collect();
    for name in Solver::NAMES {
        if verdicts::EXCLUDED.iter().any(|(s, _)| s.name() == *name) {
            continue;
        }
        assert!(
            labels.iter().any(|l| l == name),
            "{name} has no column: {labels:?}"
        );
    }
    assert!(labels.contains(&"sequential-impulse+warm".to_string()));
    let mut unique = labels.clone();
    unique.dedup();
    assert_eq!(unique, labels);
    assert_eq!(matrix().columns, labels);
    // Every row has a cell per column, and every (scene, criterion) is a row.
    let criteria: usize = SCENES.iter().map(|s| s.criteria.len()).sum();
    assert_eq!(matrix().rows.len(), criteria);
    assert!(matrix().cells.iter().all(|r| r.len() == labels.len()));
}

#[test]
fn the_json_is_the_contract() {
    let m = matrix();
    let v: serde_json::Value = serde_json::from_str(&render::json(m)).expect("JSON");
    let verdicts = v["verdicts"].as_array().expect("verdicts");
    assert_eq!(verdicts.len(), m.rows.len() * m.columns.len());
    for (j, x) in verdicts.iter().zip(m.verdicts()) {
        let keys: Vec<&str> = j.as_object().unwrap().keys().map(String::as_str).collect();
        assert_eq!(
            &keys[..5],
            ["scene", "solver", "pass", "criterion", "measured"]
        );
        assert_eq!(j["scene"], x.scene);
        assert_eq!(j["solver"], x.solver.as_str());
        assert_eq!(j["pass"], x.pass);
        assert_eq!(j["criterion"], x.criterion);
        // serde_json reads a number back to within an ulp.
        match j["measured"].as_f64() {
            Some(m) => assert!(
                (m - x.measured).abs() <= 1e-15 * x.measured.abs(),
                "{m} {x:?}"
            ),
            None => assert!(j["measured"].is_null() && !x.measured.is_finite()),
        }
        assert!(SCENES.iter().any(|s| s.id == x.scene));
    }
    assert_eq!(v["size"], "reduced");
    assert_eq!(v["not_run"], 0);
}

#[test]
fn each_cell_shows_its_verdicts_figure() {
    let m = matrix();
    let fmt = Fmt::new(3);
    let text = render::text(m, &fmt, 0);
    let svg = render::svg(m, &fmt);
    for (&(s, k), row) in m.rows.iter().zip(&m.cells) {
        let line = text
            .lines()
            .find(|l| l.starts_with(SCENES[s].id) && l.contains(SCENES[s].criteria[k].name))
            .unwrap_or_else(|| panic!("a row for {} {}", SCENES[s].id, SCENES[s].criteria[k].name));
        for v in row.iter().flatten() {
            let cell = render::cell(&fmt, v);
            let mark = if v.pass { "✓" } else { "✗" };
            if v.failure.is_none() && v.measured.is_finite() {
                assert_eq!(cell, format!("{mark} {}", fmt.num(v.measured)));
            }
            assert!(line.contains(&cell), "{line} lacks {cell}");
            assert!(svg.contains(&format!(">{cell}<")), "the SVG lacks {cell}");
            assert_eq!(
                v.pass,
                v.failure.is_none() && v.measured <= v.bound,
                "{v:?}"
            );
        }
    }
    let cells = m.rows.len() * m.columns.len();
    assert_eq!(svg.matches("<rect ").count(), 1 + cells);
    // The pass counts under the matrix are the cells' own.
    for (j, name) in m.columns.iter().enumerate() {
        let pass = m
            .cells
            .iter()
            .filter(|r| r[j].as_ref().is_some_and(|v| v.pass))
            .count();
        assert!(
            text.contains(&format!("{name} {pass} of {}", m.rows.len())),
            "{text}"
        );
    }
}

/// docs/study.md quotes every scene and criterion of the table word for word.
#[test]
fn the_criteria_are_stated_in_docs_study() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/study.md");
    let doc = std::fs::read_to_string(path).expect("docs/study.md");
    let flat = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    let doc = flat(&doc);
    for s in SCENES {
        assert!(
            doc.contains(&flat(s.what)),
            "docs/study.md lacks {}'s {:?}",
            s.id,
            s.what
        );
        for c in s.criteria {
            assert!(
                doc.contains(&flat(c.text)),
                "docs/study.md lacks {:?}",
                c.text
            );
        }
    }
}

#[test]
fn ctrl_c_before_the_start_runs_no_cell_and_says_so() {
    let m = verdicts::run(Size::Reduced, 2, &AtomicBool::new(true), &|_, _, _| {});
    assert_eq!(m.not_run, SCENES.len() * m.columns.len());
    assert!(m.cells.iter().flatten().all(Option::is_none));
    let text = render::text(&m, &Fmt::new(3), 0);
    assert!(text.contains("Interrupted"), "{text}");
    assert!(render::svg(&m, &Fmt::new(3)).contains(">not run<"));
}

/// The ramp's closed form: tan 0.25 = 0.2553 splits the five boxes three
/// sticking, two sliding at g(sin θ − μ cos θ); for every solver whose
/// verdict passes, the boxes that stick slid under 1 cm and those that slide
/// accelerate as the closed form says.
#[test]
fn the_ramp_verdicts_match_the_closed_form() {
    let scene = SCENES.iter().find(|s| s.id == "friction-ramp").unwrap();
    let lesson = verdicts::lesson(scene, Size::Reduced);
    let tan = RAMP_ANGLE.tan();
    assert!((tan - 0.2553).abs() < 5e-5);
    let mus: Vec<f64> = RAMP_BOX_FRICTION
        .iter()
        .map(|m| (m * RAMP_FRICTION).sqrt())
        .collect();
    for (mu, printed) in mus.iter().zip([0.387, 0.316, 0.265, 0.141, 0.0]) {
        assert!((mu - printed).abs() < 5e-4, "{mu} against {printed}");
    }
    let row = matrix()
        .rows
        .iter()
        .position(|&(s, _)| SCENES[s].id == "friction-ramp")
        .unwrap();
    let mut passed = 0;
    for (j, column) in columns().into_iter().enumerate() {
        let c = verdicts::config(&lesson, column);
        let steps = contact_lab::study::run::steps(scene.seconds(Size::Reduced), c.params.dt);
        let r = record::run(&lesson, &c, steps, false, &AtomicBool::new(false)).unwrap();
        let boxes = ramp_boxes(&r);
        let verdict = matrix().cells[row][j].as_ref().unwrap();
        let worst = boxes
            .iter()
            .map(|b| (b.measured - b.closed).abs())
            .fold(0.0, f64::max);
        assert_eq!(
            verdict.measured, worst,
            "the verdict's figure is the worst box's"
        );
        if !verdict.pass {
            continue;
        }
        passed += 1;
        let (s, c) = RAMP_ANGLE.sin_cos();
        for (k, b) in boxes.iter().enumerate() {
            if k < 3 {
                assert_eq!(b.closed, 0.0);
                assert!(
                    b.slid.abs() < 0.01,
                    "{}: box μ {} slid {} m",
                    column.label(),
                    b.mu,
                    b.slid
                );
            } else {
                let a = G * (s - b.mu * c);
                assert_eq!(b.closed, a);
                assert!(
                    (b.measured - a).abs() <= 0.05,
                    "{}: μ {}: {} against {a}",
                    column.label(),
                    b.mu,
                    b.measured
                );
                assert!(
                    b.slid > 0.5,
                    "{}: μ {} slid only {} m",
                    column.label(),
                    b.mu,
                    b.slid
                );
            }
        }
    }
    assert!(passed > 0, "no solver passes the ramp");
}
