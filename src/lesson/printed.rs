//! `[[printed]]` entries: numbers a lecture prints, kept with their precision.

use super::raw::{PrintedNumber, PrintedValue, RawPrinted};
use super::source::Note;
use crate::knobs::Choice;
use crate::physics::{Solver, StageId};

/// The stages beyond one contact's: `resolver` (a body's state after the
/// lesson's contacts are resolved together) and `lcp` (the simultaneous
/// impact's impulse or normal velocity after at a contact), with the
/// values each names.
pub const RESOLVED_STAGES: [(&str, &[&str]); 2] = [
    ("resolver", &["velocity", "angular_velocity"]),
    ("lcp", &["impulse", "normal_velocity_after"]),
];

/// The solvers a `stage = "resolver"` entry can name: those that resolve
/// one instant (the soft step and XPBD are time steppers, under `simulate`).
pub const RESOLVER_SOLVERS: [Solver; 3] =
    [Solver::DeepestFirst, Solver::SequentialImpulse, Solver::Lcp];

/// One printed number and how many decimals it was printed with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintedNum {
    pub value: f64,
    pub decimals: u32,
}

/// The lecture-check tolerance's units in the last printed digit.
pub const LAST_DIGIT_UNITS: f64 = 2.0;
/// The lecture-check tolerance's share of the number's size (0.1 %).
pub const RELATIVE: f64 = 1e-3;

impl PrintedNum {
    /// The lecture-check tolerance: 2 units in the last printed digit plus
    /// 0.1 % of the number's size.
    pub fn tolerance(&self) -> f64 {
        LAST_DIGIT_UNITS * 10f64.powi(-(self.decimals as i32)) + RELATIVE * self.value.abs()
    }

    pub fn agrees(&self, computed: f64) -> bool {
        (computed - self.value).abs() <= self.tolerance()
    }
}

#[derive(Debug, Clone, PartialEq)]
pub enum PrintedShape {
    Scalar(PrintedNum),
    Vector(Vec<PrintedNum>),
    Matrix(Vec<Vec<PrintedNum>>),
}

impl PrintedShape {
    pub fn numbers(&self) -> Vec<PrintedNum> {
        match self {
            PrintedShape::Scalar(n) => vec![*n],
            PrintedShape::Vector(v) => v.clone(),
            PrintedShape::Matrix(m) => m.iter().flatten().copied().collect(),
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Printed {
    pub contact: usize,
    pub stage: String,
    pub value: String,
    /// Only this component of a vector value is printed.
    pub component: Option<usize>,
    pub printed: PrintedShape,
    pub location: String,
    pub erratum: Option<String>,
    /// Where (line, column) a printed value that is all zeros stands, unless
    /// the entry marks it `deliberate = ["printed-zero"]`: `check` and the
    /// commands warn when the computed value there is not zero.
    pub zero_at: Option<(usize, usize)>,
    /// `stage = "resolver"`: the body (by name) whose state after is printed.
    pub body: Option<String>,
    /// `stage = "resolver"`: the solver named (None: the lesson's own).
    pub solver: Option<Solver>,
}

impl Printed {
    /// Whether the entry names a resolution of the lesson's contacts
    /// together (`resolver`, `lcp`), not one contact's stage.
    pub fn resolved(&self) -> bool {
        RESOLVED_STAGES.iter().any(|(s, _)| *s == self.stage)
    }
}

/// Decimals a number was written with (`1.25` → 2, `1.5e-3` → 4).
pub fn decimals_of(text: &str) -> u32 {
    let mantissa = text.split(['e', 'E']).next().unwrap_or(text);
    let exponent: i32 = text
        .split(['e', 'E'])
        .nth(1)
        .and_then(|e| e.parse().ok())
        .unwrap_or(0);
    let frac = mantissa.split('.').nth(1).map_or(0, |f| f.len() as i32);
    (frac - exponent).max(0) as u32
}

fn number(n: &PrintedNumber) -> Result<PrintedNum, String> {
    match n {
        PrintedNumber::Number(x) if x.is_finite() => Ok(PrintedNum {
            value: *x,
            decimals: decimals_of(&format!("{x}")),
        }),
        PrintedNumber::Number(x) => Err(format!("printed numbers must be finite, got {x}")),
        PrintedNumber::Text(t) => match t.trim().parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(PrintedNum {
                value: x,
                decimals: decimals_of(t.trim()),
            }),
            _ => Err(format!("\"{t}\" is not a number")),
        },
    }
}

impl Printed {
    pub fn from_raw(raw: &RawPrinted) -> Result<Printed, Note> {
        let stage = raw.stage.get_ref();
        let resolved = RESOLVED_STAGES.iter().find(|(s, _)| s == stage);
        if StageId::from_json_name(stage).is_none() && resolved.is_none() {
            return Err(Note::new(
                format!(
                    "unknown stage \"{stage}\" (stages: {}; and for the contacts resolved together: {})",
                    StageId::ALL.map(StageId::json_name).join(", "),
                    RESOLVED_STAGES.map(|(s, _)| s).join(", ")
                ),
                raw.stage.span(),
            ));
        }
        let solver = resolved_fields(raw, resolved.copied())?;
        let bad = |e: String| Note::new(e, raw.printed.span());
        let printed = match raw.printed.get_ref() {
            PrintedValue::Scalar(n) => PrintedShape::Scalar(number(n).map_err(bad)?),
            PrintedValue::Vector(v) => PrintedShape::Vector(
                v.iter()
                    .map(number)
                    .collect::<Result<_, _>>()
                    .map_err(bad)?,
            ),
            PrintedValue::Matrix(m) => PrintedShape::Matrix(
                m.iter()
                    .map(|row| row.iter().map(number).collect::<Result<Vec<_>, _>>())
                    .collect::<Result<_, _>>()
                    .map_err(bad)?,
            ),
        };
        if let Some(e) = shape_error(&printed) {
            return Err(bad(e));
        }
        if let Some(k) = &raw.component {
            let problem = if !matches!(printed, PrintedShape::Scalar(_)) {
                Some(
                    "`component` picks one number of a vector, so `printed` must be one number"
                        .to_string(),
                )
            } else if *k.get_ref() > 3 {
                Some(format!(
                    "component must be 0, 1 or 2 (3 for a quaternion's z), got {}",
                    k.get_ref()
                ))
            } else {
                None
            };
            if let Some(problem) = problem {
                return Err(Note::new(problem, k.span()));
            }
        }
        Ok(Printed {
            contact: raw.contact.as_ref().map_or(0, |c| *c.get_ref()),
            stage: stage.clone(),
            value: raw.value.get_ref().clone(),
            component: raw.component.as_ref().map(|k| *k.get_ref()),
            printed,
            location: super::ascii_minus(raw.location.get_ref()),
            erratum: raw
                .erratum
                .as_ref()
                .map(|e| super::ascii_minus(e.get_ref())),
            zero_at: None,
            body: raw.body.as_ref().map(|b| b.get_ref().clone()),
            solver,
        })
    }
}

/// The `body`, `solver` and `value` of an entry on a resolved stage (or
/// none of `body` and `solver` on a contact's stage): the solver named.
fn resolved_fields(
    raw: &RawPrinted,
    resolved: Option<(&str, &[&str])>,
) -> Result<Option<Solver>, Note> {
    let on_resolver = resolved.is_some_and(|(s, _)| s == "resolver");
    if let Some((stage, values)) = resolved {
        let value = raw.value.get_ref();
        if !values.contains(&value.as_str()) {
            return Err(Note::new(
                format!(
                    "stage \"{stage}\" has no value \"{value}\" (values: {})",
                    values.join(", ")
                ),
                raw.value.span(),
            ));
        }
    }
    match (&raw.body, on_resolver) {
        (Some(b), false) => {
            return Err(Note::new(
                "`body` belongs to stage \"resolver\" (a body's state after the contacts are resolved together)",
                b.span(),
            ))
        }
        (None, true) => {
            return Err(Note::new(
                "stage \"resolver\" needs `body = \"NAME\"`: the body whose state after is printed",
                raw.stage.span(),
            ))
        }
        _ => {}
    }
    let Some(s) = &raw.solver else {
        return Ok(None);
    };
    if !on_resolver {
        return Err(Note::new(
            "`solver` belongs to stage \"resolver\" (stage \"lcp\" is the lcp solver's)",
            s.span(),
        ));
    }
    match Solver::from_name(s.get_ref()) {
        Some(solver) if RESOLVER_SOLVERS.contains(&solver) => Ok(Some(solver)),
        Some(_) => Err(Note::new(
            format!(
                "solver \"{}\" is a time stepper, shown under `simulate`, not a resolution of one instant (solvers here: {})",
                s.get_ref(),
                RESOLVER_SOLVERS.map(|x| x.name()).join(", ")
            ),
            s.span(),
        )),
        None => Err(Note::new(
            format!(
                "unknown solver \"{}\" (solvers here: {})",
                s.get_ref(),
                RESOLVER_SOLVERS.map(|x| x.name()).join(", ")
            ),
            s.span(),
        )),
    }
}

/// What is wrong with the shape of a printed value: every value a stage has
/// is a number, a 3-vector, a quaternion (4) or a 3×3 matrix (rows of 3), so
/// anything else could never agree and is refused when the lesson is read.
fn shape_error(p: &PrintedShape) -> Option<String> {
    match p {
        PrintedShape::Scalar(_) => None,
        PrintedShape::Vector(v) if v.is_empty() => {
            Some("the printed value is empty: write the number(s) the lecture prints".into())
        }
        PrintedShape::Vector(v) if !(3..=4).contains(&v.len()) => Some(format!(
            "a printed vector has 3 numbers (4 for a quaternion), got {}",
            v.len()
        )),
        PrintedShape::Vector(_) => None,
        PrintedShape::Matrix(m) => {
            if let Some((i, row)) = m.iter().enumerate().find(|(_, r)| r.len() != 3) {
                Some(format!(
                    "a printed matrix is 3 rows of 3 numbers: row {} has {}",
                    i + 1,
                    row.len()
                ))
            } else if m.len() != 3 {
                Some(format!(
                    "a printed matrix is 3 rows of 3 numbers, got {} row(s)",
                    m.len()
                ))
            } else {
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::decimals_of;

    #[test]
    fn decimals_follow_the_printed_text() {
        assert_eq!(decimals_of("18.7337"), 4);
        assert_eq!(decimals_of("240"), 0);
        assert_eq!(decimals_of("0.10"), 2);
        assert_eq!(decimals_of("1.5e-3"), 4);
        assert_eq!(decimals_of("2e3"), 0);
    }
}
