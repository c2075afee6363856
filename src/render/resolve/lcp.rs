//! The simultaneous (lcp) velocity phase of `resolve`: the matrix A and b,
//! each pivot of Lemke's method (entering, leaving, the tableau's column,
//! the ratio test), the impulses, as text and as the JSON `"lcp"` object.

use std::fmt::Write;

use serde_json::{json, Value as J};

use crate::format::Fmt;
use crate::knobs::Choice;
use crate::physics::lcp::{Friction, Pivot, Record, Var};

/// A pivot in words: who entered, who left, the ratio.
pub fn pivot_line(k: usize, stage: &str, p: &Pivot<f64>, fmt: &Fmt) -> String {
    format!(
        "pivot {k} ({stage}): {} enters, {} leaves (row {}), ratio {}{}",
        p.entering.name(),
        p.leaving.name(),
        p.row,
        fmt.num(p.ratio),
        if p.tie {
            " (tied: lexicographic rule)"
        } else {
            ""
        }
    )
}

/// The pivot's ratio test: each row's rhs / column entry where the entry is positive.
pub fn ratio_test(p: &Pivot<f64>, fmt: &Fmt) -> String {
    if p.entering == Var::Z0 {
        return format!(
            "z0 enters at the most negative b (row {}, b = {}): every w = b + z0 >= 0 once z0 = {}",
            p.row,
            fmt.num(p.rhs[p.row]),
            fmt.num(p.ratio)
        );
    }
    let cells: Vec<String> = p
        .column
        .iter()
        .zip(&p.rhs)
        .map(|(&c, &r)| {
            if c > 0.0 {
                format!("{}/{} = {}", fmt.num(r), fmt.num(c), fmt.num(r / c))
            } else {
                "-".to_string()
            }
        })
        .collect();
    format!(
        "column [{}], rhs [{}]; ratios [{}]",
        fmt.list(&p.column),
        fmt.list(&p.rhs),
        cells.join(", ")
    )
}

/// The phase as text (the velocity phase's lines for `--solver lcp`).
pub fn text(out: &mut String, r: &Record<f64>, fmt: &Fmt) {
    let _ = writeln!(
        out,
        "   Simultaneous impact: find lambda >= 0 with w = A lambda + b >= 0 and lambda.w = 0 (Lemke's method, {} restitution)",
        r.restitution.name()
    );
    let _ = writeln!(
        out,
        "   A (contact i's normal velocity change per unit impulse at contact j):"
    );
    for row in &r.matrix {
        let _ = writeln!(out, "      [{}]", fmt.list(row));
    }
    let _ = writeln!(
        out,
        "   restitution as applied: [{}]",
        fmt.list(&r.restitutions)
    );
    let mut k = 0;
    for p in &r.problems {
        let _ = writeln!(out, "   {} LCP: b = [{}]", p.stage.name(), fmt.list(&p.b));
        if p.pivots.is_empty() && p.result.is_ok() {
            let _ = writeln!(out, "      b >= 0: lambda = 0, no pivot");
        }
        for v in &p.pivots {
            let _ = writeln!(out, "      {}", pivot_line(k, p.stage.name(), v, fmt));
            let _ = writeln!(out, "         {}", ratio_test(v, fmt));
            k += 1;
        }
        match &p.result {
            Ok(l) => {
                let _ = writeln!(out, "      lambda = [{}]", fmt.list(l));
            }
            Err(f) => {
                let _ = writeln!(out, "      {}", f.describe());
            }
        }
    }
    let _ = writeln!(out, "   impulses applied: [{}]", fmt.list(&r.impulses));
    let _ = writeln!(
        out,
        "   normal velocities after: [{}]",
        fmt.list(&r.velocities_after)
    );
    if let Some(f) = &r.friction {
        friction_text(out, f, fmt);
    }
    for note in notes(r) {
        let _ = writeln!(out, "   · {note}");
    }
}

/// The friction pass as text: what it is, then a line per contact.
fn friction_text(out: &mut String, f: &Friction<f64>, fmt: &Fmt) {
    let _ = writeln!(
        out,
        "   Friction (Coulomb, projected Gauss-Seidel after the normal LCP): each contact's tangential impulse inside the disk |lambda_t| <= mu lambda_n, lambda_n the LCP's normal impulse held fixed; sticking while inside mu_s lambda_n, else sliding at mu_d lambda_n. Exact where friction does not change the normal velocities (a sphere on a plane), an approximation where it does. {} sweep(s){}",
        f.sweeps,
        if f.converged { "" } else { ", stopped at the sweep cap without converging" }
    );
    for row in &f.rows {
        let _ = writeln!(
            out,
            "      contact {}: lambda_n {}, lambda_t ({}), {} (mu_s {}, mu_d {}); slip after ({})",
            row.contact,
            fmt.num(row.normal),
            fmt.list(&row.tangential),
            if row.sliding { "sliding" } else { "sticking" },
            fmt.num(row.static_friction),
            fmt.num(row.dynamic_friction),
            fmt.list(&row.slip_after)
        );
    }
}

/// Degeneracy, failure and friction notes.
pub fn notes(r: &Record<f64>) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(f) = r.failure() {
        out.push(format!("{}; no impulse was applied", f.describe()));
    }
    if let Some(d) = r.degenerate() {
        out.push(d);
    }
    if let Some(f) = r.friction.as_ref().filter(|f| !f.closing.is_empty()) {
        out.push(format!(
            "friction's tangential impulses left contacts {:?} closing: the normal LCP is not solved again",
            f.closing
        ));
    }
    out
}

/// The friction pass as JSON (null without friction).
fn friction_json(r: &Record<f64>) -> J {
    let Some(f) = &r.friction else {
        return J::Null;
    };
    let rows: Vec<J> = f
        .rows
        .iter()
        .map(|x| {
            json!({ "contact": x.contact, "static_friction": x.static_friction,
                    "dynamic_friction": x.dynamic_friction, "normal": x.normal,
                    "tangential": x.tangential, "sliding": x.sliding, "slip_after": x.slip_after })
        })
        .collect();
    json!({ "method": "projected-gauss-seidel", "bound": "disk mu lambda_n, lambda_n from the normal LCP",
            "sweeps": f.sweeps, "converged": f.converged, "closing": f.closing, "contacts": rows })
}

/// The JSON `"lcp"` object.
pub fn json(r: &Record<f64>) -> J {
    let pivots: Vec<J> = r
        .pivots()
        .map(|(stage, p)| {
            json!({ "stage": stage.name(), "entering": p.entering.name(), "leaving": p.leaving.name(),
                    "row": p.row, "ratio": p.ratio, "column": p.column, "rhs": p.rhs, "tie": p.tie })
        })
        .collect();
    let problems: Vec<J> = r
        .problems
        .iter()
        .map(|p| {
            json!({ "stage": p.stage.name(), "b": p.b,
                    "lambda": p.result.as_ref().ok(),
                    "failure": p.result.as_ref().err().map(|f| f.describe()) })
        })
        .collect();
    json!({
        "method": "lemke",
        "restitution": r.restitution.name(),
        "status": if r.failure().is_some() { "unsolvable" } else if r.degenerate().is_some() { "degenerate" } else { "solved" },
        "matrix": r.matrix,
        "b": r.problems.first().map(|p| p.b.clone()).unwrap_or_default(),
        "restitutions": r.restitutions,
        "problems": problems,
        "pivots": pivots,
        "impulses": r.impulses,
        "velocities_after": r.velocities_after,
        "friction": friction_json(r),
        "notes": notes(r),
    })
}
