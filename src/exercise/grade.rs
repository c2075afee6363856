//! `exercise --answer-template` and `exercise --grade ANSWERS.toml`: a
//! student's answer file, filled in from the template, graded answer by
//! answer with `trace::grade` (the lecture check's tolerance), with the
//! right answer, the difference and the score.

use std::fmt::Write;

use super::sheet::{four_decimals, short_answers};
use super::{Exercise, Kind};
use crate::exercise::answer::grade;
use crate::format::Fmt;
use crate::trace::glossary::{unit, with_unit};

/// What an answer file must say to regenerate its sheet.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SheetId {
    pub seed: u64,
    /// `mixed`, `frictionless`, `static-friction`, `dynamic-friction` or `penetration`.
    pub kind: String,
    pub count: usize,
}

/// The answer file to fill in: the sheet's id, then per exercise every
/// short answer's key with an empty string.
pub fn template(id: &SheetId, exercises: &[Exercise]) -> String {
    let mut out = format!(
        "# Answers to `contact-lab exercise --seed {} --kind {} --count {}`.\n# Write each answer as on paper, four decimals: \"2.2500\", \"(0.0000, 18.7337, 0.0000)\",\n# \"static\" or \"dynamic\"; a unit after the numbers is allowed. Leave \"\" to skip one.\n# Grade with: contact-lab exercise --grade THIS-FILE\nseed = {}\nkind = \"{}\"\ncount = {}\n",
        id.seed, id.kind, id.count, id.seed, id.kind, id.count
    );
    for e in exercises {
        let _ = writeln!(out, "\n[[exercise]]  # {}", e.lesson.title);
        for a in short_answers(e.kind, &e.trace) {
            let _ = writeln!(out, "{} = \"\"  # {}", a.key, a.label);
        }
    }
    out
}

/// The largest answer file read (a filled template for 50 exercises is
/// about 10 KiB).
pub const MAX_BYTES: usize = 1 << 20;

/// The longest answer or key echoed back, in characters (the rest is cut
/// with "…"): a report line stays a line.
const ECHO_CHARS: usize = 80;

/// Text from the answer file as echoed in a report or a message: control
/// and bidirectional characters escaped (`\u{1b}`), so the file cannot move
/// the cursor, retitle or clear the terminal, and cut after [`ECHO_CHARS`].
pub fn echo(text: &str) -> String {
    let cut: String = text.chars().take(ECHO_CHARS).collect();
    let more = if cut.len() < text.len() { "…" } else { "" };
    crate::lesson::snippet::printable(cut).replace('\n', "\\n") + more
}

/// A parser's message, which may quote the file: escaped like [`echo`],
/// its lines kept.
fn echo_message(text: &str) -> String {
    crate::lesson::snippet::printable(text.to_string())
}

/// Per exercise, the (key, answer text) pairs of an answer file.
pub type Answers = Vec<Vec<(String, String)>>;

/// Reads an answer file: the sheet id and, per exercise, key → answer text.
pub fn read(text: &str) -> Result<(SheetId, Answers), String> {
    let doc: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| echo_message(e.message()))?;
    let seed = match doc.get("seed") {
        Some(toml::Value::Integer(n)) if *n >= 0 => *n as u64,
        _ => return Err("`seed` (a whole number ≥ 0) is missing".into()),
    };
    let kind = match doc.get("kind") {
        None => "mixed".to_string(),
        Some(toml::Value::String(k)) => k.clone(),
        Some(_) => return Err("`kind` must be a string".into()),
    };
    let tables = match doc.get("exercise") {
        Some(toml::Value::Array(a)) => a.clone(),
        None => vec![],
        Some(_) => return Err("`exercise` must be an array of tables ([[exercise]])".into()),
    };
    let count = match doc.get("count") {
        Some(toml::Value::Integer(n)) if (1..=50).contains(n) => *n as usize,
        None if (1..=50).contains(&tables.len()) => tables.len(),
        _ => return Err("`count` (1 to 50) is missing".into()),
    };
    if tables.len() > count {
        return Err(format!(
            "{} [[exercise]] tables for a sheet of {count} exercise(s): one table per exercise, in order",
            tables.len()
        ));
    }
    let mut answers = Vec::new();
    for (i, t) in tables.iter().enumerate() {
        let toml::Value::Table(t) = t else {
            return Err(format!("exercise {} is not a table", i + 1));
        };
        let mut row = Vec::new();
        for (key, v) in t {
            let text = match v {
                toml::Value::String(s) => s.clone(),
                toml::Value::Float(x) => format!("{x}"),
                toml::Value::Integer(n) => n.to_string(),
                toml::Value::Array(xs) => {
                    let mut parts = Vec::new();
                    for x in xs {
                        parts.push(match x {
                            toml::Value::Float(x) => format!("{x}"),
                            toml::Value::Integer(n) => n.to_string(),
                            toml::Value::String(s) => s.clone(),
                            _ => {
                                return Err(format!(
                                    "exercise {}: `{}` holds a nested array or table; an answer is a string, a number or a list of numbers",
                                    i + 1,
                                    echo(key)
                                ))
                            }
                        });
                    }
                    format!("({})", parts.join(", "))
                }
                other => {
                    return Err(format!(
                        "exercise {}: `{}` = {} is not an answer",
                        i + 1,
                        echo(key),
                        echo(&other.to_string())
                    ))
                }
            };
            row.push((key.clone(), text));
        }
        answers.push(row);
    }
    Ok((SheetId { seed, kind, count }, answers))
}

/// A sheet's score: every answer the sheet asks counts, a blank one as
/// not right.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SheetScore {
    pub right: usize,
    pub wrong: usize,
    /// Asked and left blank (or with no table for its exercise).
    pub blank: usize,
}

impl SheetScore {
    /// Every answer the sheet asks.
    pub fn asked(&self) -> usize {
        self.right + self.wrong + self.blank
    }

    /// `1/59 (2 %): 1 right, 0 wrong, 58 blank`. The percentage is right /
    /// asked, rounded, but never 100 % unless every answer is right.
    pub fn summary(&self) -> String {
        let asked = self.asked();
        let percent = if asked == 0 {
            0
        } else if self.right < asked {
            ((100.0 * self.right as f64 / asked as f64).round() as usize).min(99)
        } else {
            100
        };
        format!(
            "{}/{asked} ({percent} %): {} right, {} wrong, {} blank",
            self.right, self.right, self.wrong, self.blank
        )
    }
}

/// The labels of one kind of answer (wrong or blank), a line per
/// exercise: `   exercise 1: v_s, Δv`.
fn by_exercise(list: &[(usize, &str)]) -> String {
    let mut parts: Vec<String> = vec![];
    let mut k = 0;
    while k < list.len() {
        let n = list[k].0;
        let labels: Vec<&str> = list[k..]
            .iter()
            .take_while(|(m, _)| *m == n)
            .map(|(_, l)| *l)
            .collect();
        k += labels.len();
        // Folded at a label (never inside one) to 80 columns, the labels
        // after the first line under the first label.
        let head = format!("   exercise {}: ", n + 1);
        let mut line = head.clone();
        for (i, label) in labels.iter().enumerate() {
            let piece = if i + 1 < labels.len() {
                format!("{label},")
            } else {
                label.to_string()
            };
            let fresh = line.chars().count() == head.chars().count();
            if !fresh && line.chars().count() + 1 + piece.chars().count() > 80 {
                parts.push(format!("{}\n", line.trim_end()));
                line = " ".repeat(head.chars().count());
            } else if !fresh {
                line.push(' ');
            }
            line.push_str(&piece);
        }
        parts.push(format!("{line}\n"));
    }
    parts.concat()
}

/// The graded file as text: per exercise each answer ✓ or ✗ with the right
/// answer and the difference, a blank one with the right answer, unknown
/// keys named; then the score over every answer the sheet asks (right /
/// asked), the wrong and the blank answers listed.
pub fn report(exercises: &[Exercise], answers: &[Vec<(String, String)>]) -> (String, SheetScore) {
    let fmt = Fmt::default();
    let mut out = String::new();
    let mut score = SheetScore::default();
    let mut wrong: Vec<(usize, &str)> = vec![];
    let mut blank: Vec<(usize, &str)> = vec![];
    for (k, e) in exercises.iter().enumerate() {
        let _ = writeln!(out, "{} ({})", e.lesson.title, kind_name(e.kind));
        let given = answers.get(k).map(Vec::as_slice).unwrap_or(&[]);
        let keys = short_answers(e.kind, &e.trace);
        for a in &keys {
            let right = with_unit(&four_decimals(a.value), unit(a.step, a.name));
            let Some((_, text)) = given
                .iter()
                .find(|(key, t)| key == a.key && !t.trim().is_empty())
            else {
                score.blank += 1;
                blank.push((k, a.label));
                let _ = writeln!(out, "   · {}: no answer (right: {right})", a.label);
                continue;
            };
            let g = grade(text, a.value);
            if g.correct {
                score.right += 1;
            } else {
                score.wrong += 1;
                wrong.push((k, a.label));
            }
            let mark = if g.correct { "✓" } else { "✗" };
            let _ = write!(out, "   {mark} {} = {}", a.label, echo(text.trim()));
            if let Some(problem) = &g.problem {
                let _ = writeln!(out, "   right: {right} ({})", echo(problem));
            } else if g.difference.is_empty() {
                let _ = writeln!(
                    out,
                    "{}",
                    if g.correct {
                        String::new()
                    } else {
                        format!("   right: {right}")
                    }
                );
            } else {
                let diff = match g.difference.as_slice() {
                    [d] => fmt.num(*d),
                    ds => format!("({})", fmt.list(ds)),
                };
                let _ = writeln!(out, "   right: {right}, difference {diff}");
            }
        }
        for (key, _) in given {
            if !keys.iter().any(|a| a.key == key) {
                let _ = writeln!(
                    out,
                    "   ? `{}` is not an answer of this exercise (not graded)",
                    echo(key)
                );
            }
        }
        out.push('\n');
    }
    let _ = writeln!(out, "Score: {}", score.summary());
    if !wrong.is_empty() {
        let _ = write!(out, "Wrong ({}):\n{}", wrong.len(), by_exercise(&wrong));
    }
    if score.blank == score.asked() && score.blank > 0 {
        let _ = writeln!(
            out,
            "Blank: all {} answers the sheet asks (a blank answer counts as not right).",
            score.blank
        );
    } else if !blank.is_empty() {
        let _ = write!(
            out,
            "Blank: {} of the {} answers the sheet asks (a blank answer counts as not right):\n{}",
            score.blank,
            score.asked(),
            by_exercise(&blank)
        );
    }
    (out, score)
}

fn kind_name(k: Kind) -> &'static str {
    k.name()
}

#[cfg(test)]
mod tests {
    /// A long list of labels folds at a label, within 80 columns, under
    /// the first label (a terminal folded it inside "dyn|amic").
    #[test]
    fn a_long_list_folds_at_a_label() {
        let labels = [
            "v_c (contact coordinates)",
            "v_s",
            "Δv",
            "M (contact coordinates)",
            "Δq̇_t",
            "sticking impulse g_contact",
            "|g_planar|",
            "g_max = μ_s g_x",
            "regime (static or dynamic)",
            "g_world",
        ];
        let list: Vec<(usize, &str)> = labels.iter().map(|l| (1, *l)).collect();
        let text = by_exercise(&list);
        let lines: Vec<&str> = text.lines().collect();
        assert!(lines.len() > 1, "{text}");
        assert!(lines.iter().all(|l| l.chars().count() <= 80), "{text}");
        // Under the first label: "   exercise 2: " is 15 columns.
        assert!(
            lines[1].starts_with(&" ".repeat(15)) && !lines[1].starts_with(&" ".repeat(16)),
            "{text}"
        );
        assert!(text.contains("regime (static or dynamic)"), "{text}");
        assert_eq!(
            text.replace('\n', " ")
                .split_whitespace()
                .collect::<Vec<_>>(),
            format!("exercise 2: {}", labels.join(", "))
                .split_whitespace()
                .collect::<Vec<_>>()
        );
    }

    use super::*;

    #[test]
    fn a_filled_template_grades_right_wrong_and_missing_answers() {
        let exercises = crate::exercise::generate(1, Some(Kind::Frictionless), 1).unwrap();
        let id = SheetId {
            seed: 1,
            kind: "frictionless".into(),
            count: 1,
        };
        let t = template(&id, &exercises);
        assert!(t.contains("dv = \"\""), "{t}");
        let (read_id, empty) = read(&t).unwrap();
        assert_eq!(read_id, id);
        // Fill in: Δv right (to four decimals), v_s wrong, the rest blank.
        let right = exercises[0]
            .trace
            .value("desired_delta_velocity", "desired")
            .unwrap()
            .clone();
        let filled = t
            .replace("dv = \"\"", &format!("dv = \"{}\"", four_decimals(&right)))
            .replace("v_s = \"\"", "v_s = \"+3\"");
        let (_, answers) = read(&filled).unwrap();
        let (text, score) = report(&exercises, &answers);
        let asked = short_answers(exercises[0].kind, &exercises[0].trace).len();
        assert!(asked > 2, "{asked}");
        assert_eq!(
            score,
            SheetScore {
                right: 1,
                wrong: 1,
                blank: asked - 2,
            },
            "{text}"
        );
        assert!(text.contains("✓ Δv = "), "{text}");
        assert!(
            text.contains("✗ v_s = +3   right: -1.6800 m/s, difference -4.68"),
            "{text}"
        );
        assert!(text.contains("· g_world: no answer"), "{text}");
        assert!(
            text.contains(&format!(
                "Score: 1/{asked} ({} %): 1 right, 1 wrong, {} blank\n",
                (100.0 / asked as f64).round(),
                asked - 2
            )),
            "{text}"
        );
        assert!(text.contains("Wrong (1):\n   exercise 1: v_s\n"), "{text}");
        assert!(
            text.contains(&format!(
                "Blank: {} of the {asked} answers the sheet asks",
                asked - 2
            )),
            "{text}"
        );
        // A blank sheet scores 0 %, every answer blank.
        let (none, score) = report(&exercises, &empty);
        assert_eq!(score.blank, asked, "{none}");
        assert!(none.contains(&format!("Score: 0/{asked} (0 %)")), "{none}");
        assert!(
            none.contains(&format!("Blank: all {asked} answers")),
            "{none}"
        );
    }

    #[test]
    fn only_a_sheet_all_right_scores_100_percent() {
        let s = |right, wrong, blank| {
            SheetScore {
                right,
                wrong,
                blank,
            }
            .summary()
        };
        assert_eq!(s(199, 0, 1), "199/200 (99 %): 199 right, 0 wrong, 1 blank");
        assert_eq!(s(3, 0, 0), "3/3 (100 %): 3 right, 0 wrong, 0 blank");
        assert_eq!(s(0, 0, 0), "0/0 (0 %): 0 right, 0 wrong, 0 blank");
    }

    #[test]
    fn a_bad_answer_file_says_what_is_missing() {
        assert!(read("kind = \"mixed\"").unwrap_err().contains("seed"));
        assert!(read("seed = 1").unwrap_err().contains("count"));
        assert!(read("seed = 1\ncount = 1\nexercise = 3")
            .unwrap_err()
            .contains("array of tables"));
    }
}
