//! The glossary (issue 16, items 1 and 2): one meaning per symbol, every
//! symbol a formula defines is in it, and the unit printed after a result is
//! the unit the glossary gives its symbol.

use contact_lab::knobs::Choice;
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
        .filter(|s| s.elsewhere.contains("the collisions lectures"))
        .map(|s| s.symbol)
        .collect();
    for s in ["g_closed", "d̂", "v_s", "μ_d"] {
        assert!(
            companion.contains(&s),
            "{s} does not say its companion name"
        );
    }
    // Issue 28: lectures are named as a reader knows them, never by file number.
    for s in GLOSSARY {
        assert!(!s.elsewhere.contains("lecture 0"), "{}", s.elsewhere);
        assert!(!s.elsewhere.contains("lectures 0"), "{}", s.elsewhere);
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

/// Issue 28, item 1: the glossary numbers the stages as the worked solution
/// and the TUI legend do (exact impact 9, checks 10), in every format, and
/// an entry's stage numbers are the ones its stage ids have.
#[test]
fn the_glossary_numbers_the_stages_as_the_worked_solution_does() {
    use contact_lab::physics::StageId;
    assert_eq!(StageId::ExactImpact.number(), 9);
    assert_eq!(StageId::Checks.number(), 10);
    let text = contact_lab::render::glossary::text();
    assert!(
        text.contains("stages: 1 contact frame … 10 checks"),
        "{text}"
    );
    assert!(!text.contains("9 checks"), "{text}");
    let md = contact_lab::render::glossary::markdown();
    assert!(md.contains("3 desired Δv,"), "{md}");
    assert!(md.contains("9 integration, 10 checks."), "{md}");
    let tex = contact_lab::render::glossary::latex();
    assert!(tex.contains("9 integration, 10 checks."), "{tex}");
    assert!(!tex.contains("9 checks"), "{tex}");
    let pen = GLOSSARY
        .iter()
        .find(|s| s.stages.contains(&StageId::Checks))
        .unwrap();
    assert!(pen.stage_numbers().split(", ").any(|n| n == "10"));
}

/// Issue 28, item 1: a label in running text lowers its first letter only
/// (the TUI breadcrumb showed "desired δv").
#[test]
fn a_label_in_text_keeps_its_greek_capitals() {
    use contact_lab::physics::StageId;
    assert_eq!(StageId::DesiredDeltaVelocity.label_in_text(), "desired Δv");
    assert_eq!(StageId::ContactFrame.label_in_text(), "contact frame");
}

/// Issue 28, item 1: no worked solution, under any friction model, names a
/// lecture by its internal file number ("seed 004's model", "seeds 002/003").
#[test]
fn worked_solutions_name_the_lectures_by_title() {
    let fmt = contact_lab::format::Fmt::default();
    let mut said = 0;
    for t in traces() {
        let text = contact_lab::render::contact::text::render(&t, &fmt);
        for stale in [
            "seed 0",
            "Seed 0",
            "seeds 0",
            "Seeds 0",
            "(002/003)",
            "lectures 00",
        ] {
            assert!(!text.contains(stale), "«{stale}» in\n{text}");
        }
        said +=
            usize::from(text.contains("PSE Friction") || text.contains("Lecture IV Collisions"));
    }
    assert!(said > 0, "no worked solution names a companion lecture");
}
