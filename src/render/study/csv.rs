//! The study as CSV: one line per scene and configuration, every knob and
//! every metric in full precision, empty where not a number. Without timing
//! the timing columns are absent.

use crate::study::{Row, Study};

/// A CSV field: quoted when it holds a comma, a quote or a line break.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn number(x: f64) -> String {
    if x.is_finite() {
        format!("{x}")
    } else {
        String::new()
    }
}

pub fn render(study: &Study) -> String {
    let knobs: Vec<&str> = study
        .scenes
        .first()
        .and_then(|s| s.rows.first())
        .map(|r| r.config.knobs().into_iter().map(|(k, _)| k).collect())
        .unwrap_or_default();
    let mut head = vec!["scene", "knob", "value"];
    head.extend(knobs.iter().copied());
    if study.timed {
        head.extend([
            "microseconds_per_step",
            "microseconds_min",
            "microseconds_max",
            "microseconds_per_second",
        ]);
    }
    head.extend([
        "contact_visits_per_step",
        "ccd_tests_per_step",
        "limit_steps",
        "steps",
        "work_per_second",
        "max_penetration",
        "max_closing_velocity",
        "energy_gain",
        "drift",
        "missed_collisions",
        "error_vs_reference",
        "pareto",
    ]);
    let mut out = head.join(",") + "\n";
    for s in &study.scenes {
        for r in &s.rows {
            out.push_str(&line(&s.scene, r, study.timed));
        }
    }
    out
}

fn line(scene: &str, r: &Row, timed: bool) -> String {
    let mut f = vec![field(scene), field(&r.knob), field(&r.value)];
    f.extend(r.config.knobs().into_iter().map(|(_, v)| field(&v)));
    if timed {
        let [m, lo, hi] = r.microseconds.unwrap_or([f64::NAN; 3]);
        let per_second = r.microseconds_per_second.map_or(f64::NAN, |t| t[0]);
        f.extend([number(m), number(lo), number(hi), number(per_second)]);
    }
    f.extend([
        number(r.visits_per_step),
        number(r.ccd_tests_per_step),
        r.limit_steps.to_string(),
        r.steps.to_string(),
        number(r.work_per_second),
        number(r.max_penetration),
        number(r.max_closing_velocity),
        number(r.energy_gain),
        number(r.drift),
        r.missed_collisions.to_string(),
        number(r.error_vs_reference),
        r.pareto.to_string(),
    ]);
    f.join(",") + "\n"
}
