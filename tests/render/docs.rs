//! `docs/json.md` against the code: its stage sections come in the order of
//! `StageId::ALL`, every value name a solution produces is documented under
//! its stage, and every name the tables list is produced by some lesson.

use crate::common;

use std::collections::{BTreeMap, BTreeSet};

use contact_lab::lesson::Overrides;
use contact_lab::physics::StageId;

/// Stage id → the backticked words of its section, and the words of the
/// first column of its tables.
fn documented() -> Vec<(String, BTreeSet<String>, BTreeSet<String>)> {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/json.md"))
        .expect("docs/json.md");
    let body = text
        .split("## Stages and their values")
        .nth(1)
        .expect("stage section")
        .split("## Skipped stages")
        .next()
        .unwrap();
    let ticked = |s: &str| -> Vec<String> {
        s.split('`')
            .skip(1)
            .step_by(2)
            .map(str::to_string)
            .collect()
    };
    body.split("\n### ")
        .skip(1)
        .map(|section| {
            let heading = section.lines().next().unwrap();
            let id = ticked(heading).into_iter().next().expect("stage id");
            let all = ticked(section).into_iter().collect();
            let first_column = section
                .lines()
                .filter(|l| l.starts_with("| `"))
                .flat_map(|l| ticked(l.split(" | ").next().unwrap()))
                .collect();
            (id, all, first_column)
        })
        .collect()
}

/// Stage id → every value name some embedded lesson produces, under every
/// friction model, both projections and no angular limit.
fn produced() -> BTreeMap<String, BTreeSet<String>> {
    let variants = [
        Overrides::default(),
        Overrides::from_pairs(&[("friction_model", "kinetic-direction")]).unwrap(),
        Overrides::from_pairs(&[("friction_model", "velocity-scaling")]).unwrap(),
        Overrides::from_pairs(&[("projection", "linear")]).unwrap(),
        Overrides::from_pairs(&[("angular_limit", "inf")]).unwrap(),
        Overrides::from_pairs(&[("exact", "stronge")]).unwrap(),
    ];
    let mut names: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for lesson in common::all_lessons() {
        for o in &variants {
            let mut l = lesson.clone();
            l.apply(o);
            for k in 0..l.contacts.len() {
                for step in contact_lab::worked_solution(&l, k).stages {
                    let set = names.entry(step.id.json_name().to_string()).or_default();
                    set.extend(step.values.into_iter().map(|(n, _)| n.into_owned()));
                }
            }
        }
    }
    names
}

#[test]
fn the_stage_sections_come_in_stage_order() {
    let ids: Vec<String> = documented().into_iter().map(|(id, _, _)| id).collect();
    let code: Vec<&str> = StageId::ALL.iter().map(|s| s.json_name()).collect();
    assert_eq!(ids, code);
}

#[test]
fn every_value_produced_is_documented_and_every_documented_one_produced() {
    let produced = produced();
    for (id, all, first_column) in documented() {
        let made = &produced[&id];
        for name in made {
            // A row for body 1 covers body 2 ("… `2`").
            let as_body1 = name.replace('2', "1");
            assert!(
                all.contains(name) || all.contains(&as_body1),
                "{id}.{name} is produced but not in docs/json.md"
            );
        }
        for name in &first_column {
            if name.starts_with('…') || name.chars().all(|c| c.is_ascii_digit()) {
                continue;
            }
            assert!(
                made.contains(name),
                "docs/json.md lists {id}.{name}, which no lesson produces"
            );
        }
    }
}
