//! The glossary (issue 16, items 1 and 2): one meaning per symbol, every
//! symbol a formula defines is in it, and the unit printed after a result is
//! the unit the glossary gives its symbol.

use std::collections::HashMap;

use contact_lab::lesson::{Lesson, Overrides};
use contact_lab::physics::FrictionModel;
use contact_lab::trace::glossary::{symbols_in, unit, GLOSSARY};
use contact_lab::trace::Trace;

/// Every trace the worked solutions can show: every lesson contact under
/// every friction model, and with linear and relaxed projection.
fn traces() -> Vec<Trace> {
    let mut out = Vec::new();
    for id in contact_lab::lesson::embedded::ids() {
        let variants = FrictionModel::ALL
            .iter()
            .map(|m| Overrides::from_pairs(&[("friction_model", m.name())]).unwrap())
            .chain([
                Overrides::from_pairs(&[("projection", "linear"), ("relaxation", "0.5")]).unwrap(),
            ]);
        for o in variants {
            let mut l = Lesson::load(id).unwrap();
            l.apply(&o);
            for k in 0..l.contacts.len() {
                out.push(contact_lab::worked_solution(&l, k));
            }
        }
    }
    out
}

/// The glossary entry whose name (ᵢ standing for ₁ or ₂) is `lhs`.
fn entry(lhs: &str) -> Option<&'static contact_lab::trace::glossary::Symbol> {
    GLOSSARY.iter().find(|s| {
        s.symbol.split(", ").any(|name| {
            ["ᵢ", "₁", "₂"]
                .iter()
                .any(|sub| name.replace('ᵢ', sub) == lhs)
        })
    })
}

#[test]
fn no_two_meanings_share_a_symbol() {
    let mut seen: HashMap<&str, &str> = HashMap::new();
    for s in GLOSSARY {
        for name in s.symbol.split(", ") {
            if let Some(other) = seen.insert(name, s.meaning) {
                panic!("{name} means both «{other}» and «{}»", s.meaning);
            }
        }
    }
    let mut meanings: HashMap<&str, &str> = HashMap::new();
    for s in GLOSSARY {
        if let Some(other) = meanings.insert(s.meaning, s.symbol) {
            panic!("«{}» has two symbols: {other} and {}", s.meaning, s.symbol);
        }
    }
}

#[test]
fn every_symbol_a_formula_defines_is_in_the_glossary_with_the_unit_it_prints() {
    let mut checked = 0;
    for t in traces() {
        for step in &t.stages {
            for f in &step.formulas {
                // Expressions on the left (q̇₁ · d̂, Δ_a₁ (limited)) are made of symbols.
                if f.lhs.contains(' ') {
                    assert!(!symbols_in(&f.lhs).is_empty(), "{}: {}", t.lesson, f.lhs);
                    continue;
                }
                let e = entry(&f.lhs).unwrap_or_else(|| {
                    panic!(
                        "{} {}: «{}» is not in the glossary",
                        t.lesson,
                        step.id.json_name(),
                        f.lhs
                    )
                });
                assert!(
                    e.stages.contains(&step.id),
                    "{}: the glossary does not list stage {} for {}",
                    t.lesson,
                    step.id.json_name(),
                    e.symbol
                );
                if let Some(r) = &f.result {
                    assert_eq!(
                        unit(step, r),
                        e.unit,
                        "{} {}: {} = {r} printed with another unit than the glossary's",
                        t.lesson,
                        step.id.json_name(),
                        f.lhs
                    );
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 1000, "only {checked} formulas checked");
}

#[test]
fn the_companion_lectures_names_are_said_once() {
    let companion: Vec<&str> = GLOSSARY
        .iter()
        .filter(|s| s.elsewhere.contains("002/003"))
        .map(|s| s.symbol)
        .collect();
    for s in ["g_closed", "d̂", "v_s", "μ_d"] {
        assert!(
            companion.contains(&s),
            "{s} does not say its companion name"
        );
    }
}

#[test]
fn the_glossary_command_prints_every_symbol_in_each_format() {
    for format in ["text", "md", "latex", "json"] {
        let out = assert_cmd::Command::cargo_bin("contact-lab")
            .unwrap()
            .args(["glossary", "--format", format])
            .output()
            .unwrap();
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).unwrap();
        assert!(text.contains("restitution"), "{format}");
        if format == "text" {
            for s in GLOSSARY {
                assert!(text.contains(s.symbol), "{} missing", s.symbol);
            }
        }
    }
}
