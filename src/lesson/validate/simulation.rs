//! Validation of the time-stepping tables (`[world]`, `[step]`, `[sleep]`)
//! and of the per-body fields only scenes use (a half-space's `normal`, the
//! coefficients of generated contacts).

use super::super::raw::{KnobTable, RawBody, RawLesson, S};
use super::super::Material;
use super::{rules, v3, Validator};
use crate::knobs::Table;
use crate::physics::params::SceneSettings;
use crate::physics::{Settings, Shape};

/// `restitution`, `friction`, `static_friction`, `dynamic_friction` as written.
type MaterialFields<'a> = (
    &'a Option<S<f64>>,
    &'a Option<S<f64>>,
    &'a Option<S<f64>>,
    &'a Option<S<f64>>,
);

/// The coefficients `[world]` gives every body (not knobs: data of the scene).
const MATERIAL_FIELDS: [&str; 4] = [
    "restitution",
    "friction",
    "static_friction",
    "dynamic_friction",
];

impl Validator {
    /// Every knob of the lesson's tables, over the defaults (a scene's when
    /// the lesson has any of `[world]`, `[step]`, `[sleep]`), and the scene,
    /// when it has one.
    pub(super) fn knobs(&mut self, raw: &RawLesson) -> (Settings, Option<SceneSettings>) {
        let scene = raw.world.is_some() || raw.step.is_some() || raw.sleep.is_some();
        let mut all = if scene {
            Settings::scene_default()
        } else {
            Settings::default()
        };
        self.knob_table(Table::Settings, &raw.settings, &mut all, &[]);
        if let Some(w) = &raw.world {
            self.knob_table(Table::World, w, &mut all, &MATERIAL_FIELDS);
            let fields = MATERIAL_FIELDS.map(|f| self.number_field(w, f));
            all.scene.material = self.material(
                "[world]",
                Material::default(),
                (&fields[0], &fields[1], &fields[2], &fields[3]),
            );
        }
        if let Some(step) = &raw.step {
            self.knob_table(Table::Step, step, &mut all, &[]);
        }
        if let Some(sleep) = &raw.sleep {
            self.knob_table(Table::Sleep, sleep, &mut all, &[]);
        }
        let simulation = scene.then(|| all.scene.clone());
        (all, simulation)
    }

    /// A number field of a table read as a map.
    fn number_field(&mut self, table: &KnobTable, name: &str) -> Option<S<f64>> {
        let (_, value) = table.iter().find(|(k, _)| k.get_ref() == name)?;
        match value.get_ref() {
            toml::Value::Float(x) => Some(S::new(value.span(), *x)),
            toml::Value::Integer(n) => Some(S::new(value.span(), *n as f64)),
            _ => {
                self.err(value.span(), format!("{name} must be a number"));
                None
            }
        }
    }

    /// Restitution and friction coefficients over `base` (the one rule of
    /// [`Material::with`]: `friction` sets both, μ_d defaults to μ_s).
    pub(super) fn material(
        &mut self,
        table: &str,
        base: Material,
        (restitution, friction, mu_s, mu_d): MaterialFields,
    ) -> Material {
        let what = format!("{table} ");
        let mut read = |x: &Option<S<f64>>, name: &str, rule: fn(f64) -> Result<(), String>| {
            x.as_ref()
                .map(|x| self.rule(&format!("{what}{name}"), x, rule))
        };
        let e = read(restitution, "restitution", rules::restitution);
        let mu = read(friction, "friction", rules::friction);
        let s = read(mu_s, "static_friction", rules::friction);
        let d = read(mu_d, "dynamic_friction", rules::friction);
        base.with(e, mu, s, d)
    }

    /// Each body's coefficients: `[world]`'s, overridden by the body's own
    /// fields. Without time stepping the body fields are refused, since
    /// nothing would read them.
    pub(super) fn body_materials(&mut self, raw: &RawLesson, sim: Option<&mut SceneSettings>) {
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
