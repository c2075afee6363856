//! Validation of the resolver's settings (`position_iterations`,
//! `velocity_iterations`, `position_epsilon`, `velocity_epsilon`,
//! `restitution_from`, `solver`, `warm_start`): the lesson's `[settings]` only, refused in a
//! contact's `settings`.

use super::super::raw::{RawSettings, S};
use super::{rules, Validator};
use crate::physics::{ResolverParams, RestitutionFrom, Solver};

impl Validator {
    /// The resolver's settings of the lesson's `[settings]` table.
    pub(super) fn resolver(&mut self, raw: &RawSettings) -> ResolverParams {
        let mut p = ResolverParams::default();
        let iterations = |v: &mut Self, name: &str, x: &Option<S<i64>>| {
            let x = x.as_ref()?;
            match rules::iterations(name, *x.get_ref()) {
                Ok(()) => Some(*x.get_ref() as usize),
                Err(e) => {
                    v.err(x.span(), format!("in [settings]: {e}"));
                    None
                }
            }
        };
        p.position_iterations = iterations(self, "position_iterations", &raw.position_iterations);
        p.velocity_iterations = iterations(self, "velocity_iterations", &raw.velocity_iterations);
        for (name, x, out) in [
            (
                "position_epsilon",
                &raw.position_epsilon,
                &mut p.position_epsilon,
            ),
            (
                "velocity_epsilon",
                &raw.velocity_epsilon,
                &mut p.velocity_epsilon,
            ),
        ] {
            if let Some(x) = x {
                match rules::epsilon(name, *x.get_ref()) {
                    Ok(()) => *out = *x.get_ref(),
                    Err(e) => self.err(x.span(), format!("in [settings]: {e}")),
                }
            }
        }
        if let Some(r) = &raw.restitution_from {
            match RestitutionFrom::from_name(r.get_ref()) {
                Some(m) => p.restitution_from = m,
                None => self.err(
                    r.span(),
                    format!(
                        "in [settings]: restitution_from must be \"current\" or \"initial\", got \"{}\"",
                        r.get_ref()
                    ),
                ),
            }
        }
        if let Some(x) = &raw.solver {
            match Solver::from_name(x.get_ref()) {
                Some(m) => p.solver = m,
                None => self.err(
                    x.span(),
                    format!(
                        "in [settings]: solver must be \"deepest_first\" or \"sequential_impulse\", got \"{}\"",
                        x.get_ref()
                    ),
                ),
            }
        }
        if let Some(w) = &raw.warm_start {
            p.warm_start = *w.get_ref();
        }
        p
    }

    /// A contact's `settings` table cannot hold the resolver's (scene-wide) settings.
    pub(super) fn no_resolver_settings(&mut self, raw: &RawSettings) {
        let spans = [
            (
                "position_iterations",
                raw.position_iterations.as_ref().map(|x| x.span()),
            ),
            (
                "velocity_iterations",
                raw.velocity_iterations.as_ref().map(|x| x.span()),
            ),
            (
                "position_epsilon",
                raw.position_epsilon.as_ref().map(|x| x.span()),
            ),
            (
                "velocity_epsilon",
                raw.velocity_epsilon.as_ref().map(|x| x.span()),
            ),
            (
                "restitution_from",
                raw.restitution_from.as_ref().map(|x| x.span()),
            ),
            ("solver", raw.solver.as_ref().map(|x| x.span())),
            ("warm_start", raw.warm_start.as_ref().map(|x| x.span())),
        ];
        for (name, span) in spans {
            if let Some(span) = span {
                self.err(
                    span,
                    format!("{name} is a setting of the whole scene: put it in the lesson's [settings], not in a contact's settings"),
                );
            }
        }
    }
}
