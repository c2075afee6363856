//! The glossary's soft-step and XPBD quantities: every value a soft-step
//! trace prints (its JSON keys, the names its text gives) has an entry with
//! its formula and meaning, and the glossary command prints them.

use std::collections::BTreeSet;

use assert_cmd::Command;
use contact_lab::trace::glossary::{solver_symbol_by_key, SOLVER_GLOSSARY};

/// Keys that place a value (which contact, which bodies, which record)
/// rather than name a quantity.
const PLACES: [&str; 6] = ["solver", "step", "contact", "contacts", "body1", "body2"];

fn keys(v: &serde_json::Value, out: &mut BTreeSet<String>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, v) in m {
                out.insert(k.clone());
                keys(v, out);
            }
        }
        serde_json::Value::Array(a) => a.iter().for_each(|v| keys(v, out)),
        _ => {}
    }
}

fn soft_trace(format: &str) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args([
            "simulate",
            "resting-box",
            "--solver",
            "soft-step",
            "--trace-step",
            "3",
            "--format",
            format,
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn every_value_a_soft_step_trace_prints_has_a_glossary_entry() {
    let json: serde_json::Value = serde_json::from_str(&soft_trace("json")).unwrap();
    let mut all = BTreeSet::new();
    keys(&json, &mut all);
    let missing: Vec<&String> = all
        .iter()
        .filter(|k| !PLACES.contains(&k.as_str()) && solver_symbol_by_key(k).is_none())
        .collect();
    assert!(missing.is_empty(), "no glossary entry for {missing:?}");
    // The names the text gives the soft coefficients.
    let text = soft_trace("text");
    for name in [
        "h",
        "f",
        "ζ",
        "ω",
        "a₁",
        "a₂",
        "a₃",
        "bias rate",
        "mass scale",
        "impulse scale",
        "push-out speed",
        "relax",
    ] {
        assert!(text.contains(name), "the trace no longer prints {name}");
        assert!(
            SOLVER_GLOSSARY.iter().any(|s| s.symbol == name),
            "no glossary entry for {name}"
        );
    }
}

#[test]
fn the_xpbd_quantities_have_their_formulas() {
    for (symbol, formula) in [
        ("α̃", "α̃ = α/h²"),
        ("Δλ_n", "Δλ_n = (-C - α̃λ_n)/(w + α̃)"),
        ("a₁", "a₁ = 2ζ + hω"),
        ("bias rate", "ω/a₁"),
    ] {
        let e = SOLVER_GLOSSARY
            .iter()
            .find(|s| s.symbol == symbol)
            .unwrap_or_else(|| panic!("{symbol}"));
        assert_eq!(e.formula, formula);
        assert!(!e.meaning.is_empty());
    }
    for s in SOLVER_GLOSSARY {
        assert!(!s.formula.contains('\u{2212}') && !s.meaning.contains('\u{2212}'));
    }
}

#[test]
fn the_glossary_command_prints_the_solver_quantities() {
    let run = |format: &str| {
        let out = Command::cargo_bin("contact-lab")
            .unwrap()
            .args(["glossary", "--format", format])
            .output()
            .unwrap();
        assert!(out.status.success());
        String::from_utf8(out.stdout).unwrap()
    };
    let text = run("text");
    let md = run("md");
    for s in SOLVER_GLOSSARY {
        assert!(text.contains(s.meaning), "text: {}", s.symbol);
        assert!(
            md.contains(&s.symbol.replace('|', "\\|")),
            "md: {}",
            s.symbol
        );
    }
    let json: serde_json::Value = serde_json::from_str(&run("json")).unwrap();
    assert_eq!(
        json["solver_symbols"].as_array().map(Vec::len),
        Some(SOLVER_GLOSSARY.len())
    );
}

/// A step of stack-5 under `solver`, recorded by the step itself.
fn record(solver: contact_lab::physics::Solver) -> contact_lab::trace::substeps::SubstepsRecord {
    use contact_lab::trace::substeps;
    let lesson = contact_lab::lesson::Lesson::load("stack-5").unwrap();
    let mut params = lesson.sim_params().unwrap();
    params.resolver.solver = solver;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = contact_lab::physics::step::Simulation::new(
        world,
        params,
        lesson.simulation.unwrap().materials,
    );
    for _ in 0..4 {
        sim.advance().unwrap();
    }
    assert!(substeps::ask(&mut sim));
    sim.advance().unwrap();
    substeps::take(&mut sim).expect("a record")
}

/// The left-hand sides the TUI's substep lines print (`X = value`): each
/// is a glossary symbol, or the formula of one (`ω/a₁`, `a₂a₃`, `α/h²`).
#[test]
fn every_symbol_the_tuis_substep_lines_print_has_a_glossary_entry() {
    use contact_lab::physics::Solver;
    use contact_lab::tui::screens::resolver_substeps::lines;
    let f = contact_lab::format::Fmt::new(4);
    let mut seen = BTreeSet::new();
    for solver in [Solver::SoftStep, Solver::Xpbd] {
        let rec = record(solver);
        for text in lines(&rec, 0, 0, &f) {
            let words: Vec<&str> = text.split_whitespace().collect();
            for w in words.windows(2).filter(|w| w[1] == "=") {
                let lhs = w[0].trim_start_matches(['(', '›']);
                seen.insert(lhs.to_string());
            }
        }
    }
    let missing: Vec<&String> = seen
        .iter()
        .filter(|lhs| {
            !SOLVER_GLOSSARY.iter().any(|s| {
                s.symbol == lhs.as_str()
                    || s.formula == lhs.as_str()
                    || s.formula.ends_with(&format!("= {lhs}"))
            })
        })
        .collect();
    assert!(
        missing.is_empty(),
        "no glossary entry for {missing:?} (of {seen:?})"
    );
    assert!(seen.len() >= 12, "{seen:?}");
}
