//! Grading a student's answer against a value of the trace (predict mode in
//! the TUI, `exercise --grade`): parse a scalar, vector or word, compare it
//! with the tolerance of the lecture check (2 units in the answer's last
//! digit, at four decimals at most, plus 0.1 % of its size), report the
//! right answer and the difference, and keep a score. Pure functions, no I/O.

use crate::lesson::printed::{decimals_of, PrintedNum};
use crate::trace::Value;

/// One graded answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Grade {
    pub correct: bool,
    /// What the student gave, as parsed (numbers) or written (a word).
    pub given: Vec<f64>,
    /// The right answer's numbers (empty for a word answer).
    pub expected: Vec<f64>,
    /// expected - given, component by component (empty for a word answer).
    pub difference: Vec<f64>,
    /// The tolerance each component was judged with.
    pub tolerance: Vec<f64>,
    /// Why the answer could not be compared (wrong number of components,
    /// a word for a number), when it could not.
    pub problem: Option<String>,
}

/// The numbers of an answer with the decimals each was written with:
/// `18.73`, `-1.25 m/s`, `(0, 18.7337, 0)`, `[1, 0, 0, -0.0687]`,
/// `0 18.73 0`. Unicode minus signs, brackets, commas and a trailing unit
/// are accepted.
pub fn parse(answer: &str) -> Result<Vec<PrintedNum>, String> {
    let cleaned: String = answer
        .replace(['−', '–'], "-")
        .chars()
        .map(|c| if "()[]{};".contains(c) { ' ' } else { c })
        .collect();
    let mut numbers = Vec::new();
    for token in cleaned
        .split([',', ' ', '\t', '\n'])
        .filter(|t| !t.is_empty())
    {
        match token.parse::<f64>() {
            Ok(x) if x.is_finite() => numbers.push(PrintedNum {
                value: x,
                decimals: decimals_of(token.trim_start_matches(['-', '+'])),
            }),
            Ok(_) => return Err(format!("«{}» is not a finite number", quoted(token))),
            // A unit after the numbers (m/s, N·s, °) is allowed; a stray word is not.
            Err(_) if !numbers.is_empty() && is_unit(token) => {}
            Err(_) => return Err(format!("«{}» is not a number", quoted(token))),
        }
    }
    if numbers.is_empty() {
        return Err("no number in the answer".into());
    }
    Ok(numbers)
}

fn is_unit(token: &str) -> bool {
    token
        .chars()
        .all(|c| c.is_alphabetic() || "/·°²⁻¹*^-".contains(c) || c.is_ascii_digit())
        && token.chars().any(|c| c.is_alphabetic() || c == '°')
}

/// A token of the answer quoted in a problem: its first 16 characters
/// (the whole answer is echoed beside the problem already), control
/// characters escaped.
fn quoted(token: &str) -> String {
    let cut: String = token.chars().take(16).collect();
    let more = if cut.len() < token.len() { "…" } else { "" };
    crate::lesson::snippet::printable(cut) + more
}

/// Grades `answer` against `expected`. Numbers: every component within the
/// lecture-check tolerance of the component the student wrote. Words (the
/// friction regime): the same word, or `sticks`/`slides` for
/// `static`/`dynamic`.
pub fn grade(answer: &str, expected: &Value) -> Grade {
    if let Value::Text(word) = expected {
        let given = answer.trim().to_lowercase();
        let alias = match given.as_str() {
            "sticks" | "stick" | "sticking" => "static",
            "slides" | "slide" | "sliding" | "kinetic" => "dynamic",
            other => other,
        };
        return Grade {
            correct: alias == word.as_str(),
            given: vec![],
            expected: vec![],
            difference: vec![],
            tolerance: vec![],
            problem: None,
        };
    }
    let want = expected.numbers();
    let fail = |problem: String, given: Vec<f64>| Grade {
        correct: false,
        given,
        expected: want.clone(),
        difference: vec![],
        tolerance: vec![],
        problem: Some(problem),
    };
    let got = match parse(answer) {
        Ok(got) => got,
        Err(e) => return fail(e, vec![]),
    };
    let given: Vec<f64> = got.iter().map(|n| n.value).collect();
    if got.len() != want.len() {
        let what = match want.len() {
            1 => "one number".to_string(),
            n => format!("{n} numbers"),
        };
        return fail(
            format!("the answer has {} number(s); {what} expected", got.len()),
            given,
        );
    }
    let tolerance: Vec<f64> = got.iter().map(tolerance).collect();
    let difference: Vec<f64> = want.iter().zip(&given).map(|(w, g)| w - g).collect();
    Grade {
        correct: difference
            .iter()
            .zip(&tolerance)
            .all(|(d, t)| d.abs() <= *t),
        given,
        expected: want,
        difference,
        tolerance,
        problem: None,
    }
}

/// The fewest decimals a written number's tolerance is counted at.
pub const MIN_DECIMALS: u32 = 4;

/// The lecture check's tolerance for a number written like `n` (2 units in
/// its last digit plus 0.1 %), counted at four decimals at most: writing
/// fewer digits ("20" for 18.7337, "1" for 0.0000007) does not buy a wider
/// tolerance than the sheet's "work to four decimals".
pub fn tolerance(n: &PrintedNum) -> f64 {
    PrintedNum {
        decimals: n.decimals.max(MIN_DECIMALS),
        ..*n
    }
    .tolerance()
}

/// The score of a lesson or an exercise sheet.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Score {
    pub correct: usize,
    pub graded: usize,
}

impl Score {
    pub fn record(&mut self, g: &Grade) {
        self.graded += 1;
        if g.correct {
            self.correct += 1;
        }
    }

    /// `7/9 (78 %)`.
    pub fn summary(&self) -> String {
        let percent = if self.graded == 0 {
            0
        } else {
            (100.0 * self.correct as f64 / self.graded as f64).round() as usize
        };
        format!("{}/{} ({percent} %)", self.correct, self.graded)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scalars_vectors_units_and_unicode_minus_parse() {
        let v = |s: &str| {
            parse(s)
                .unwrap()
                .iter()
                .map(|n| n.value)
                .collect::<Vec<_>>()
        };
        assert_eq!(v("18.7337"), vec![18.7337]);
        assert_eq!(v("(0, 18.7337, 0) N·s"), vec![0.0, 18.7337, 0.0]);
        assert_eq!(v("[1, 0, 0, −0.0687]"), vec![1.0, 0.0, 0.0, -0.0687]);
        assert_eq!(v("-1.25 m/s"), vec![-1.25]);
        assert_eq!(v("0 18.73 0"), vec![0.0, 18.73, 0.0]);
        assert_eq!(parse("2.25").unwrap()[0].decimals, 2);
        assert_eq!(parse("−0.0687").unwrap()[0].decimals, 4);
        assert!(parse("about twenty").is_err());
        assert!(parse("").is_err());
        assert!(parse("m/s").is_err(), "a unit alone is not an answer");
    }

    #[test]
    fn an_answer_within_the_check_tolerance_is_right() {
        let g = grade("18.73", &Value::Scalar(18.733766));
        assert!(g.correct, "{g:?}");
        assert!((g.difference[0] - 0.003766).abs() < 1e-9);
        // Two units in the fourth decimal + 0.1 % (0.0189): 18.69 is out.
        assert!(!grade("18.69", &Value::Scalar(18.733766)).correct);
        // Fewer digits do not widen the tolerance.
        assert!(!grade("20", &Value::Scalar(18.733766)).correct);
        assert!(!grade("1", &Value::Scalar(6.9e-7)).correct);
        // The lecture's erratum (0, 18, 7337, 0) has four numbers: not comparable.
        let g = grade("(0, 18, 7337, 0)", &Value::Vector([0.0, 18.7337, 0.0]));
        assert!(!g.correct);
        assert!(g.problem.unwrap().contains("3 numbers expected"));
    }

    #[test]
    fn vectors_are_graded_component_by_component() {
        let right = Value::Vector([2.165, 0.62337, 0.0]);
        assert!(grade("(2.165, 0.6234, 0)", &right).correct);
        let g = grade("(2.165, -0.6234, 0)", &right);
        assert!(!g.correct);
        assert!((g.difference[1] - 1.24677).abs() < 1e-9);
        assert_eq!(g.expected, vec![2.165, 0.62337, 0.0]);
    }

    #[test]
    fn the_regime_is_graded_as_a_word() {
        assert!(grade("sticks", &Value::Text("static".into())).correct);
        assert!(grade("Dynamic", &Value::Text("dynamic".into())).correct);
        assert!(!grade("static", &Value::Text("dynamic".into())).correct);
    }

    #[test]
    fn the_score_counts_right_answers() {
        let mut s = Score::default();
        s.record(&grade("2.25", &Value::Scalar(2.25)));
        s.record(&grade("2.5", &Value::Scalar(2.25)));
        s.record(&grade("0.1201", &Value::Scalar(0.120104)));
        assert_eq!(
            s,
            Score {
                correct: 2,
                graded: 3
            }
        );
        assert_eq!(s.summary(), "2/3 (67 %)");
    }
}
