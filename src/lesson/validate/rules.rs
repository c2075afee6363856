//! Rules shared by the file validator and the TUI's edit form: each returns
//! the reason a value is refused.

use crate::format::exact;
use crate::lesson::ranges;
pub use crate::lesson::ranges::{in_range, MAX_MAGNITUDE, MIN_MAGNITUDE};

/// Zero, or a magnitude from 1e-60 to 1e60 (see `lesson::ranges` for why).
pub fn finite(x: f64) -> Result<(), String> {
    ranges::problem(x).map_or(Ok(()), Err)
}
/// The inertia tensor the stages will use (see `lesson::ranges::inertia`).
pub fn inertia(t: &nalgebra::Matrix3<f64>) -> Result<(), String> {
    ranges::inertia(t)
}
pub fn mass(m: f64) -> Result<(), String> {
    if m.is_nan() || m <= 0.0 {
        Err(format!(
            "mass must be > 0 (or inf for an immovable body), got {}",
            exact(m)
        ))
    } else if !(1.0 / m).is_finite() {
        Err(format!(
            "mass {m:e} is too small: its inverse 1/m overflows a 64-bit float"
        ))
    } else if m.is_finite() && !(in_range(m) && in_range(1.0 / m)) {
        Err(format!(
            "mass {m:e} is outside contact-lab's range of 1e-60 to 1e60 (use inf for an immovable body)"
        ))
    } else {
        Ok(())
    }
}
pub fn restitution(c: f64) -> Result<(), String> {
    if (0.0..=1.0).contains(&c) {
        Ok(())
    } else {
        Err(format!("restitution must be in [0, 1], got {}", exact(c)))
    }
}
pub fn friction(mu: f64) -> Result<(), String> {
    if in_range(mu) && mu >= 0.0 {
        Ok(())
    } else if mu > 0.0 && mu < MIN_MAGNITUDE {
        Err(format!("friction coefficient {}", ranges::too_small(mu)))
    } else if mu.is_finite() && mu > 0.0 {
        Err(format!(
            "friction coefficient {mu:e} is outside contact-lab's range of 0 to 1e60"
        ))
    } else {
        Err(format!(
            "friction coefficient must be a finite number ≥ 0, got {}",
            exact(mu)
        ))
    }
}
/// Ids and names appear in headings and tables: not blank, no control
/// characters at all (see `lesson::characters`).
pub fn name(s: &str) -> Result<(), String> {
    if s.trim().is_empty() {
        Err("must not be empty".into())
    } else {
        super::super::characters::name(s)
    }
}
/// One-line texts (title, source, a printed entry's value and where).
pub fn line(s: &str) -> Result<(), String> {
    super::super::characters::line(s)
}
/// Multi-line texts (summary, erratum): line breaks and tabs, no other
/// control characters.
pub fn text(s: &str) -> Result<(), String> {
    super::super::characters::lines(s)
}
