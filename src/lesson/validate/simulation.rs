//! Validation of the time-stepping tables (`[world]`, `[step]`, `[sleep]`)
//! and of the per-body fields only scenes use (a half-space's `normal`, the
//! coefficients of generated contacts).

use super::super::raw::{RawBody, RawLesson, S};
use super::super::{Material, Simulation};
use super::{rules, v3, Validator};
use crate::physics::params::BoxBoxMode;
use crate::physics::step::SleepMode;
use crate::physics::Shape;

/// `restitution`, `friction`, `static_friction`, `dynamic_friction` as written.
type MaterialFields<'a> = (
    &'a Option<S<f64>>,
    &'a Option<S<f64>>,
    &'a Option<S<f64>>,
    &'a Option<S<f64>>,
);

/// The most steps a lesson may ask for (a longer run is a loop, not a lesson).
pub const MAX_STEPS: i64 = 10_000_000;

impl Validator {
    /// `Some` when the lesson has any of `[world]`, `[step]`, `[sleep]`.
    pub(super) fn simulation(&mut self, raw: &RawLesson) -> Option<Simulation> {
        if raw.world.is_none() && raw.step.is_none() && raw.sleep.is_none() {
            return None;
        }
        let mut sim = Simulation::default();
        if let Some(w) = &raw.world {
            if let Some(g) = &w.gravity {
                sim.world.gravity = v3(self.finite("[world] gravity", g));
            }
            let damping = |v: &mut Validator, x: &Option<S<f64>>, what: &str, out: &mut f64| {
                if let Some(x) = x {
                    *out = v.rule(&format!("[world] {what}"), x, damping_rule);
                }
            };
            damping(
                self,
                &w.linear_damping,
                "linear_damping",
                &mut sim.world.linear_damping,
            );
            damping(
                self,
                &w.angular_damping,
                "angular_damping",
                &mut sim.world.angular_damping,
            );
            if let Some(m) = &w.box_box {
                match BoxBoxMode::from_name(m.get_ref()) {
                    Some(mode) => sim.box_box = mode,
                    None => self.err(
                        m.span(),
                        format!(
                            "[world] box_box must be \"single\" or \"manifold\", got \"{}\"",
                            m.get_ref()
                        ),
                    ),
                }
            }
            if let Some(v) = &w.velocity_limit {
                sim.velocity_limit = self.rule("[world] velocity_limit", v, rules::velocity_limit);
            }
            if let Some(m) = &w.friction_model {
                match crate::physics::FrictionModel::from_name(m.get_ref()) {
                    Some(model) => sim.friction_model = model,
                    None => self.err(
                        m.span(),
                        format!("[world] friction_model must be one of millington, kinetic-direction, velocity-scaling; got \"{}\"", m.get_ref()),
                    ),
                }
            }
            if let Some(m) = &w.contact_margin {
                sim.contact_margin = self.rule("[world] contact_margin", m, rules::non_negative);
            }
            if let Some(a) = &w.acceleration_compensation {
                sim.acceleration_compensation = *a.get_ref();
            }
            sim.material = self.material(
                "[world]",
                Material::default(),
                (
                    &w.restitution,
                    &w.friction,
                    &w.static_friction,
                    &w.dynamic_friction,
                ),
            );
        }
        if let Some(step) = &raw.step {
            if let Some(dt) = &step.dt {
                sim.dt = self.rule("[step] dt", dt, rules::duration);
            }
            if let Some(n) = &step.steps {
                let steps = *n.get_ref();
                if !(0..=MAX_STEPS).contains(&steps) {
                    self.err(
                        n.span(),
                        format!("[step] steps must be between 0 and {MAX_STEPS}, got {steps}"),
                    );
                } else {
                    sim.steps = steps as u64;
                }
            }
        }
        if let Some(sleep) = &raw.sleep {
            if let Some(e) = &sleep.enabled {
                sim.sleep.enabled = *e.get_ref();
            }
            if let Some(e) = &sleep.epsilon {
                sim.sleep.epsilon = self.rule("[sleep] epsilon", e, rules::non_negative);
            }
            if let Some(t) = &sleep.island_time {
                sim.sleep.island_time = self.rule("[sleep] island_time", t, rules::non_negative);
            }
            if let Some(m) = &sleep.mode {
                match SleepMode::from_name(m.get_ref()) {
                    Some(mode) => sim.sleep.mode = mode,
                    None => self.err(
                        m.span(),
                        format!(
                            "[sleep] mode must be \"body\" or \"island\", got \"{}\"",
                            m.get_ref()
                        ),
                    ),
                }
            }
        }
        Some(sim)
    }

    /// Restitution and friction coefficients over `base`: `friction` sets
    /// both, `static_friction` / `dynamic_friction` each one.
    pub(super) fn material(
        &mut self,
        table: &str,
        base: Material,
        (restitution, friction, mu_s, mu_d): MaterialFields,
    ) -> Material {
        let mut m = base;
        let what = format!("{table} ");
        if let Some(c) = restitution {
            m.restitution = self.rule(&format!("{what}restitution"), c, rules::restitution);
        }
        if let Some(mu) = friction {
            let mu = self.rule(&format!("{what}friction"), mu, rules::friction);
            m.static_friction = mu;
            m.dynamic_friction = mu;
        }
        if let Some(mu) = mu_s {
            m.static_friction = self.rule(&format!("{what}static_friction"), mu, rules::friction);
        }
        if let Some(mu) = mu_d {
            m.dynamic_friction = self.rule(&format!("{what}dynamic_friction"), mu, rules::friction);
        }
        m
    }

    /// Each body's coefficients: `[world]`'s, overridden by the body's own
    /// fields. Without time stepping the body fields are refused, since
    /// nothing would read them.
    pub(super) fn body_materials(&mut self, raw: &RawLesson, sim: Option<&mut Simulation>) {
        let Some(sim) = sim else {
            for b in &raw.bodies {
                let given = [
                    &b.restitution,
                    &b.friction,
                    &b.static_friction,
                    &b.dynamic_friction,
                ];
                if let Some(x) = given.into_iter().flatten().next() {
                    self.err(
                        x.span(),
                        format!(
                            "body '{}': its own restitution and friction are for generated contacts; add a [world] or [step] table, or give them on the [[contact]]",
                            b.name.get_ref()
                        ),
                    );
                }
            }
            return;
        };
        for b in &raw.bodies {
            let movable = b.mass.get_ref().is_finite();
            if movable && b.shape.is_none() {
                self.err(
                    b.name.span(),
                    format!(
                        "body '{}' moves in a scene (the lesson has [world], [step] or [sleep]) and needs a `shape` to collide",
                        b.name.get_ref()
                    ),
                );
            }
        }
        sim.materials = raw
            .bodies
            .iter()
            .map(|b| {
                self.material(
                    &format!("body '{}'", b.name.get_ref()),
                    sim.material,
                    (
                        &b.restitution,
                        &b.friction,
                        &b.static_friction,
                        &b.dynamic_friction,
                    ),
                )
            })
            .collect();
    }

    /// A half-space's normal: required non-zero and normalised; refused on
    /// any other shape.
    pub(super) fn half_space_normal(
        &mut self,
        name: &str,
        raw: &RawBody,
        shape: &mut Option<Shape>,
    ) {
        let Some(n) = &raw.normal else {
            return;
        };
        // A direction: any non-zero length will do (scaled before squaring,
        // so a length of 1e-170 is not taken for zero).
        let v = v3(self.finite_direction(&format!("body '{name}' normal"), n));
        match shape {
            Some(Shape::HalfSpace { normal }) => {
                let len = crate::physics::scale::stable_norm(&v);
                if len == 0.0 || !len.is_finite() {
                    self.err(
                        n.span(),
                        format!("body '{name}': a half-space's normal must be non-zero"),
                    );
                } else {
                    *normal = super::super::ranges::flush_tiny(v / len).into();
                }
            }
            _ => self.err(
                n.span(),
                format!("body '{name}': `normal` is only for a half_space shape"),
            ),
        }
    }
}

/// A damping: the fraction of velocity kept per second, in (0, 1] and not
/// below 1e-60 (also `simulate --damping`).
pub fn damping_rule(x: f64) -> Result<(), String> {
    if x > 0.0 && x < rules::MIN_MAGNITUDE {
        Err(format!(
            "damping {}",
            super::super::ranges::too_small_positive(x)
        ))
    } else if x > 0.0 && x <= 1.0 {
        Ok(())
    } else {
        Err(format!(
            "damping is the fraction of velocity kept per second and must be in (0, 1], got {}",
            crate::format::exact(x)
        ))
    }
}
