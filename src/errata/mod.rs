//! Errata: every number a lesson prints (`[[printed]]`) against the value
//! the trace computes — agrees, known erratum, or new disagreement. Pure:
//! lessons and traces in, findings out (the `check` subcommand). A value of
//! the contacts resolved together (`resolver`, `lcp`) comes from the
//! resolver's trace ([`resolved`]).
//! - `xpbd.rs`: the XPBD paper's dynamic-friction erratum, measured on a
//!   sliding box when asked (beside the lecture's).

pub mod resolved;
pub mod xpbd;

use crate::lesson::printed::{PrintedNum, PrintedShape};
use crate::lesson::{Lesson, Printed};
use crate::trace::{Trace, Value};

/// How a printed number compares with the computed one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Within 2 units of the last printed digit plus 0.1 % of its size.
    Agrees,
    /// Disagrees, and the lesson documents why (an erratum).
    KnownErratum,
    /// Disagrees and nothing explains it.
    NewDisagreement,
    /// Agrees, yet the lesson calls it an erratum: the note is out of date.
    StaleErratum,
    /// The stage, value or component named does not exist in the trace.
    NotComputed,
}

impl Status {
    pub fn name(self) -> &'static str {
        match self {
            Status::Agrees => "agrees",
            Status::KnownErratum => "known erratum",
            Status::NewDisagreement => "new disagreement",
            Status::StaleErratum => "stale erratum",
            Status::NotComputed => "not computed",
        }
    }

    /// Whether this finding lets `check` succeed.
    pub fn ok(self) -> bool {
        matches!(self, Status::Agrees | Status::KnownErratum)
    }
}

/// One printed entry, compared.
#[derive(Debug, Clone, PartialEq)]
pub struct Item {
    pub lesson: String,
    pub contact: usize,
    pub stage: String,
    pub value: String,
    /// What the worked solution calls the value (`Δv` for `desired`), the
    /// key itself when nothing names it.
    pub label: String,
    /// What a resolved entry's value is of (`after the resolver, lcp`),
    /// in place of the stage's words; None on a contact's stage.
    pub scope: Option<String>,
    pub component: Option<usize>,
    pub location: String,
    pub printed: PrintedShape,
    /// The computed value in the printed value's place (one component when
    /// `component` is set); `None` when the trace has no such value.
    pub computed: Option<Value>,
    pub agrees: bool,
    pub erratum: Option<String>,
    pub status: Status,
}

/// Whether every printed number is within tolerance of its computed one; a
/// different count of numbers disagrees.
pub fn agrees(printed: &[PrintedNum], computed: &[f64]) -> bool {
    printed.len() == computed.len() && printed.iter().zip(computed).all(|(p, c)| p.agrees(*c))
}

fn computed(trace: Option<&Trace>, p: &Printed) -> Option<Value> {
    pick(trace?.value(&p.stage, &p.value)?.clone(), p)
}

/// The printed entry's component of `value` (all of it when none is named).
fn pick(value: Value, p: &Printed) -> Option<Value> {
    match p.component {
        None => Some(value),
        Some(i) => value.numbers().get(i).map(|x| Value::Scalar(*x)),
    }
}

/// The computed value of `p`: from contact `p.contact`'s trace, or for a
/// resolved entry from the resolution it names.
fn computed_in(
    lesson: &Lesson,
    traces: &[Trace],
    p: &Printed,
    all: &mut resolved::Resolutions,
) -> Option<Value> {
    if p.resolved() {
        return pick(resolved::value(lesson, p, all)?, p);
    }
    computed(traces.get(p.contact), p)
}

/// Compares one printed entry with the traces of its lesson (one per
/// contact; the resolutions a resolved entry needs are computed in `all`).
pub fn item(
    lesson: &Lesson,
    traces: &[Trace],
    p: &Printed,
    all: &mut resolved::Resolutions,
) -> Item {
    let computed = computed_in(lesson, traces, p, all);
    let (label, scope) = if p.resolved() {
        let (label, scope) = resolved::label(lesson, p);
        (label, Some(scope))
    } else {
        let label = traces
            .get(p.contact)
            .and_then(|t| t.symbol(&p.stage, &p.value))
            .unwrap_or_else(|| p.value.clone());
        (label, None)
    };
    let agrees = computed
        .as_ref()
        .is_some_and(|c| agrees(&p.printed.numbers(), &c.numbers()));
    let status = match (&computed, agrees, &p.erratum) {
        (None, _, _) => Status::NotComputed,
        (_, true, None) => Status::Agrees,
        (_, true, Some(_)) => Status::StaleErratum,
        (_, false, Some(_)) => Status::KnownErratum,
        (_, false, None) => Status::NewDisagreement,
    };
    Item {
        lesson: lesson.id.clone(),
        contact: p.contact,
        stage: p.stage.clone(),
        value: p.value.clone(),
        label,
        scope,
        component: p.component,
        location: p.location.clone(),
        printed: p.printed.clone(),
        computed,
        agrees,
        erratum: p.erratum.clone(),
        status,
    }
}

/// Every printed entry of a lesson, in the order the lesson lists them.
pub fn lesson(lesson: &Lesson, traces: &[Trace]) -> Vec<Item> {
    let mut all = resolved::Resolutions::default();
    lesson
        .printed
        .iter()
        .map(|p| item(lesson, traces, p, &mut all))
        .collect()
}

/// The load warnings of printed values that are all zeros where the
/// computed value is not (a printed `0` agrees with anything below 2, so
/// the comparison proves little): `path:line:column: …`, one per entry
/// not marked `deliberate = ["printed-zero"]`. `trace` gives contact k's
/// worked solution, asked only for the contacts such entries name.
pub fn zero_warnings(lesson: &Lesson, mut trace: impl FnMut(usize) -> Trace) -> Vec<String> {
    let mut traces: Vec<(usize, Trace)> = Vec::new();
    let mut all = resolved::Resolutions::default();
    let mut out = Vec::new();
    for p in &lesson.printed {
        let Some((line, column)) = p.zero_at else {
            continue;
        };
        let c = if p.resolved() {
            resolved::value(lesson, p, &mut all).and_then(|v| pick(v, p))
        } else {
            if !traces.iter().any(|(k, _)| *k == p.contact) {
                traces.push((p.contact, trace(p.contact)));
            }
            let t = traces.iter().find(|(k, _)| *k == p.contact).map(|(_, t)| t);
            computed(t, p)
        };
        let Some(c) = c else {
            continue;
        };
        if c.numbers().iter().any(|x| x.abs() > 1e-9) {
            let f = crate::format::Fmt::default();
            let shown = match &c {
                Value::Scalar(x) => f.num(*x),
                other => format!("({})", f.list(&other.numbers())),
            };
            let printed = match &p.printed {
                PrintedShape::Scalar(_) => "0".to_string(),
                other => format!("({})", vec!["0"; other.numbers().len()].join(", ")),
            };
            out.push(format!(
                "{}:{line}:{column}: printed {printed} for {}.{} ({}) is compared with the computed {shown}, which is not zero: a printed zero agrees with any small value, so the check proves little. Print the decimals the lecture shows, or mark the entry `deliberate = [\"printed-zero\"]`",
                lesson.origin, p.stage, p.value, p.location
            ));
        }
    }
    out
}

/// Counts of each status, in the order of [`Status`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Tally {
    pub agrees: usize,
    pub known: usize,
    pub new: usize,
    pub stale: usize,
    pub not_computed: usize,
}

impl Tally {
    pub fn of<'a>(items: impl IntoIterator<Item = &'a Item>) -> Tally {
        let mut t = Tally::default();
        for i in items {
            match i.status {
                Status::Agrees => t.agrees += 1,
                Status::KnownErratum => t.known += 1,
                Status::NewDisagreement => t.new += 1,
                Status::StaleErratum => t.stale += 1,
                Status::NotComputed => t.not_computed += 1,
            }
        }
        t
    }

    /// Problems that make `check` fail.
    pub fn failures(&self) -> usize {
        self.new + self.stale + self.not_computed
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lesson::validate::parse;

    const SCENE: &str = r#"
id = "t"
title = "t"
[[body]]
name = "ball"
mass = 2.0
shape = { sphere = 1.0 }
position = [0.0, 1.0, 0.0]
velocity = [0.0, -2.0, 0.0]
[[contact]]
bodies = ["ball"]
point = [0.0, 0.0, 0.0]
normal = [0.0, 1.0, 0.0]
restitution = 0.5
"#;

    fn items(printed: &str) -> Vec<Item> {
        let l = parse("t.toml", &format!("{SCENE}{printed}")).unwrap();
        let traces = vec![crate::worked_solution(&l, 0)];
        lesson(&l, &traces)
    }

    #[test]
    fn statuses() {
        let found = items(
            r#"
[[printed]]
stage = "desired_delta_velocity"
value = "desired"
printed = 3.0
where = "right"
[[printed]]
stage = "desired_delta_velocity"
value = "desired"
printed = 3.5
where = "wrong, explained"
erratum = "a slip"
[[printed]]
stage = "desired_delta_velocity"
value = "desired"
printed = 3.5
where = "wrong"
[[printed]]
stage = "desired_delta_velocity"
value = "desired"
printed = 3.0
where = "right, yet called wrong"
erratum = "old note"
[[printed]]
stage = "desired_delta_velocity"
value = "no_such_value"
printed = 3.0
where = "typo in the name"
[[printed]]
stage = "apply_impulse"
value = "v1"
printed = [0, 1, 0, 0]
where = "a vector of four numbers"
[[printed]]
stage = "apply_impulse"
value = "v1"
component = 1
printed = 1.0
where = "one component"
"#,
        );
        let statuses: Vec<Status> = found.iter().map(|i| i.status).collect();
        assert_eq!(
            statuses,
            vec![
                Status::Agrees,
                Status::KnownErratum,
                Status::NewDisagreement,
                Status::StaleErratum,
                Status::NotComputed,
                Status::NewDisagreement,
                Status::Agrees,
            ]
        );
        assert_eq!(found[6].computed, Some(Value::Scalar(1.0)));
        let t = Tally::of(&found);
        assert_eq!((t.agrees, t.known, t.failures()), (2, 1, 4));
    }

    #[test]
    fn tolerance_is_two_units_of_the_last_digit_plus_a_tenth_of_a_percent() {
        let p = PrintedNum {
            value: 18.7337,
            decimals: 4,
        };
        // 2e-4 + 0.0187337
        assert!(agrees(&[p], &[18.7337 + 0.0189]));
        assert!(!agrees(&[p], &[18.7337 + 0.0190]));
        assert!(!agrees(&[p, p], &[18.7337]));
    }
}
