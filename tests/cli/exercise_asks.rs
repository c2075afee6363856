//! Exercises grade what they ask (issue 28, item 3): for every kind of
//! sheet, the quantities its questions ask for are the fields of
//! `--answer-template`, the lines of the answer key (`--answers`) and the
//! answers the grader marks; exercise 1's v_c and g in contact coordinates
//! among them.

use assert_cmd::Command;
use contact_lab::exercise::asked::{questions, short_answers};
use contact_lab::exercise::grade::{report, template, SheetId};
use contact_lab::exercise::sheet::four_decimals;
use contact_lab::exercise::{generate, Kind};

fn stdout(args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "contact-lab {args:?}");
    String::from_utf8(out.stdout).unwrap()
}

const KINDS: [(Kind, &str); 4] = [
    (Kind::Frictionless, "frictionless"),
    (Kind::StaticFriction, "static-friction"),
    (Kind::DynamicFriction, "dynamic-friction"),
    (Kind::Penetration, "penetration"),
];

#[test]
fn asked_equals_template_equals_key_equals_graded_for_every_sheet() {
    for (kind, name) in KINDS {
        for seed in [1u64, 7] {
            let exercises = generate(seed, Some(kind), 2).unwrap();
            let seed_text = seed.to_string();
            let args = [
                "exercise", "--seed", &seed_text, "--kind", name, "--count", "2",
            ];
            let sheet = stdout(&[&args[..], &["--answers"]].concat());
            let file = stdout(&[&args[..], &["--answer-template"]].concat());
            let id = SheetId {
                seed,
                kind: name.into(),
                count: 2,
            };
            assert_eq!(file, template(&id, &exercises));
            let template_sections: Vec<&str> = file.split("[[exercise]]").skip(1).collect();
            let key_sections: Vec<&str> = sheet
                .split("# Answers")
                .nth(1)
                .unwrap()
                .split("\n## ")
                .skip(1)
                .collect();
            let mut filled = file.clone();
            for (i, e) in exercises.iter().enumerate() {
                let answers = short_answers(e.kind, &e.trace);
                // Asked: every key of every question that this scene has a value for.
                let asked: Vec<&str> = questions(e.kind, &e.trace)
                    .iter()
                    .flat_map(|q| q.asks.iter().copied())
                    .filter(|k| answers.iter().any(|a| a.key == *k))
                    .collect::<std::collections::BTreeSet<_>>()
                    .into_iter()
                    .collect();
                let mut keys: Vec<&str> = answers.iter().map(|a| a.key).collect();
                keys.sort_unstable();
                assert_eq!(asked, keys, "{name} seed {seed} exercise {}", i + 1);
                let mut fields: Vec<&str> = template_sections[i]
                    .lines()
                    .filter_map(|l| l.split_once(" = \"\"").map(|(k, _)| k))
                    .collect();
                fields.sort_unstable();
                assert_eq!(
                    fields,
                    keys,
                    "template, {name} seed {seed} exercise {}",
                    i + 1
                );
                // The short answers: the first list under the exercise's title.
                let key_lines: Vec<&str> = key_sections[i]
                    .lines()
                    .skip(1)
                    .skip_while(|l| l.is_empty())
                    .take_while(|l| l.starts_with("- "))
                    .collect();
                assert_eq!(key_lines.len(), answers.len(), "{name}: {key_lines:?}");
                for (line, a) in key_lines.iter().zip(&answers) {
                    assert!(line.starts_with(&format!("- {} = ", a.label)), "{line}");
                }
                // The grader marks each of them, right when filled from the key.
                let section = template_sections[i];
                let mut right = section.to_string();
                for a in &answers {
                    right = right.replacen(
                        &format!("{} = \"\"", a.key),
                        &format!("{} = \"{}\"", a.key, four_decimals(a.value)),
                        1,
                    );
                }
                filled = filled.replacen(section, &right, 1);
            }
            let (_, answers) = contact_lab::exercise::grade::read(&filled).unwrap();
            let (text, score) = report(&exercises, &answers);
            let asked: usize = exercises
                .iter()
                .map(|e| short_answers(e.kind, &e.trace).len())
                .sum();
            assert_eq!((score.right, score.asked()), (asked, asked), "{text}");
        }
    }
}

#[test]
fn exercise_one_asks_for_v_c_and_g_in_contact_coordinates_and_grades_them() {
    let e = &generate(1, Some(Kind::Frictionless), 1).unwrap()[0];
    let first = questions(e.kind, &e.trace)[0];
    assert!(first.text.contains("v_c") && first.asks.contains(&"v_c"));
    let file = stdout(&[
        "exercise",
        "--seed",
        "1",
        "--kind",
        "frictionless",
        "--count",
        "1",
        "--answer-template",
    ]);
    assert!(file.contains("\nv_c = \"\""), "{file}");
    assert!(file.contains("\ng_contact = \"\""), "{file}");
    let sheet = stdout(&[
        "exercise",
        "--seed",
        "1",
        "--kind",
        "frictionless",
        "--count",
        "1",
        "--answers",
    ]);
    let key = &sheet[sheet.find("# Answers").unwrap()..];
    assert!(key.contains("\n- v_c (contact coordinates) = ("), "{key}");
    assert!(key.contains("\n- g_contact = ("), "{key}");
}
