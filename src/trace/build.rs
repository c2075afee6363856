//! Builds the [`Trace`] of one contact from its stage records: formulas,
//! the numbers put into them (as `{name}` placeholders), results and notes.

use nalgebra::Vector3;

use super::latex::to_latex;
use super::scene::scene;
use super::{AfterState, Formula, Step, Trace, Value, Verdict};
use crate::lesson::Lesson;
use crate::physics::checks::CheckKind;
use crate::physics::solve::{Skip, Solution};
use crate::physics::stages::friction::FrictionIssue;
use crate::physics::stages::*;
use crate::physics::{FrictionModel, Problem, ProjectionMethod};

const SUB: [&str; 2] = ["₁", "₂"];

/// Builds the trace of contact `k` of `lesson`, solved as `solution`.
pub fn build(lesson: &Lesson, k: usize, solution: &Solution<f64>) -> Trace {
    let problem = lesson.problem::<f64>(k);
    let ctx = Ctx {
        lesson,
        k,
        problem: &problem,
        s: solution,
    };
    let stages = vec![
        ctx.contact_frame(),
        ctx.unit_impulse(),
        ctx.desired(),
        ctx.impulse(),
        ctx.friction(),
        ctx.apply(),
        ctx.projection(),
        ctx.orientation(),
        ctx.checks(),
    ];
    let slots = lesson.slots(k);
    let after = (0..2)
        .filter_map(|i| {
            let a = solution.after(&problem, i)?;
            let name = lesson.bodies[slots[i]?].name.clone();
            Some((
                name,
                AfterState {
                    position: a.position.into(),
                    orientation: [
                        a.orientation.w,
                        a.orientation.i,
                        a.orientation.j,
                        a.orientation.k,
                    ],
                    velocity: a.velocity.into(),
                    angular_velocity: a.angular_velocity.into(),
                },
            ))
        })
        .collect();
    Trace {
        lesson: lesson.id.clone(),
        title: lesson.title.clone(),
        source: lesson.source.clone(),
        summary: lesson.summary.clone(),
        contact: k,
        contact_label: lesson.contact_label(k),
        bodies: lesson.contact_body_names(k),
        stages,
        after,
        verdicts: ctx.verdicts(),
        warnings: lesson.warnings.iter().map(|w| w.to_string()).collect(),
        scene: scene(lesson, k, solution),
    }
}

struct Ctx<'a> {
    lesson: &'a Lesson,
    k: usize,
    problem: &'a Problem<f64>,
    s: &'a Solution<f64>,
}

/// Collects one stage.
struct B {
    step: Step,
}

impl B {
    fn new(id: &'static str, title: &'static str) -> Self {
        B {
            step: Step {
                id,
                title,
                skipped: None,
                formulas: vec![],
                inputs: vec![],
                values: vec![],
                notes: vec![],
            },
        }
    }
    fn input(&mut self, name: impl Into<String>, v: impl Into<Value>) {
        self.step.inputs.push((name.into(), v.into()));
    }
    fn value(&mut self, name: impl Into<String>, v: impl Into<Value>) {
        self.step.values.push((name.into(), v.into()));
    }
    /// `lhs = rhs = substituted = {result}`.
    fn f(&mut self, lhs: &str, rhs: &str, substituted: Option<&str>, result: Option<&str>) {
        self.step.formulas.push(Formula {
            lhs: lhs.to_string(),
            rhs: rhs.to_string(),
            substituted: substituted.map(str::to_string),
            result: result.map(str::to_string),
            latex: format!("{} = {}", to_latex(lhs), to_latex(rhs)),
            substituted_latex: substituted.map(to_latex),
        });
    }
    fn note(&mut self, text: impl Into<String>) {
        self.step.notes.push(text.into());
    }
    fn skipped(mut self, why: &str) -> Step {
        self.step.skipped = Some(why.to_string());
        self.step
    }
    fn done(self) -> Step {
        self.step
    }
}

fn skip_reason(skip: Skip) -> &'static str {
    match skip {
        Skip::Separating => {
            "the contact is separating or at rest (Δv ≤ 0): the resolver applies no impulse"
        }
        Skip::NoFriction => "no friction (μ = 0): the impulse acts along the normal only",
        Skip::NoPenetration => "no penetration (d_pen ≤ 0): nothing to project",
        Skip::NoRotation => "the projection rotates no body (no angular share)",
    }
}

/// True when the normal passes through the centre to within the data's
/// rounding: the angle between r and d̂ has sine below 10⁻⁴ (the lecture's
/// four-digit data leaves about 5·10⁻⁵).
fn through_centre(r: &Vector3<f64>, d: &Vector3<f64>) -> bool {
    crate::physics::scale::stable_norm(&r.cross(d)) <= 1e-4 * crate::physics::scale::stable_norm(r)
}

/// `Some((axis letter, counter_clockwise))` when `v` lies along one world axis.
fn about_one_axis(v: &Vector3<f64>) -> Option<(char, bool)> {
    let n = crate::physics::scale::stable_norm(v);
    if n == 0.0 {
        return None;
    }
    let i = v.iamax();
    let others = (0..3)
        .filter(|&j| j != i)
        .map(|j| v[j].abs())
        .fold(0.0, f64::max);
    (others <= 1e-9 * n).then(|| (['x', 'y', 'z'][i], v[i] > 0.0))
}

fn sense(ccw: bool) -> &'static str {
    if ccw {
        "counter-clockwise"
    } else {
        "clockwise"
    }
}

impl Ctx<'_> {
    fn name(&self, i: usize) -> String {
        let slot = self.lesson.slots(self.k)[i];
        slot.map_or_else(
            || "the world".to_string(),
            |b| self.lesson.bodies[b].name.clone(),
        )
    }

    /// Movable slots.
    fn movable(&self) -> Vec<usize> {
        (0..2)
            .filter(|&i| self.problem.bodies[i].is_some())
            .collect()
    }

    fn body(&self, i: usize) -> &crate::physics::RigidBody<f64> {
        self.problem.bodies[i].as_ref().expect("movable slot")
    }

    /// Bodies named in the contact that are immovable.
    fn immovable_named(&self) -> Vec<usize> {
        let slots = self.lesson.slots(self.k);
        (0..2)
            .filter(|&i| slots[i].is_some() && self.problem.bodies[i].is_none())
            .collect()
    }

    fn contact_frame(&self) -> Step {
        let mut b = B::new("contact_frame", "Contact frame");
        let f = &self.s.frame;
        let c = &self.lesson.contacts[self.k];
        let d = f.normal();
        b.input("q", self.problem.contact.point);
        b.input("d", d);
        let guess = match f.guess {
            crate::physics::frame::GuessAxis::X => (Vector3::x(), "x"),
            crate::physics::frame::GuessAxis::Y => (Vector3::y(), "y"),
        };
        b.input("guess", guess.0);
        b.value("contact_to_world", f.contact_to_world);
        b.value("normal", d);
        b.value("tangent0", f.contact_to_world.column(1).into_owned());
        b.value("tangent1", f.contact_to_world.column(2).into_owned());
        b.f(
            "t₀",
            "g × d̂ / |g × d̂|",
            Some("{guess} × {d} / |{guess} × {d}|"),
            Some("tangent0"),
        );
        b.f("t₁", "d̂ × t₀", Some("{d} × {tangent0}"), Some("tangent1"));
        b.f("C", "[d̂ t₀ t₁]", None, Some("contact_to_world"));
        for i in self.movable() {
            let n = i + 1;
            b.input(format!("p{n}"), self.body(i).position);
            b.value(format!("r{n}"), f.r[i].unwrap_or_default());
            b.f(
                &format!("r{}", SUB[i]),
                &format!("q − p{}", SUB[i]),
                Some(&format!("{{q}} − {{p{n}}}")),
                Some(&format!("r{n}")),
            );
        }
        b.note(format!(
            "The guess axis is world {} because |d.x| {} |d.y|; the basis columns d̂, t₀, t₁ are orthonormal and right-handed (t₁ = d̂ × t₀).",
            guess.1,
            if guess.1 == "y" { ">" } else { "≤" }
        ));
        if (c.normal_length - 1.0).abs() > 1e-12 {
            b.input("normal_length_deviation", c.normal_length - 1.0);
            b.note("The normal as written has length 1 + ({normal_length_deviation}); it was normalised before use.");
        }
        for i in self.movable() {
            let n = i + 1;
            if let Some(digits) = f.r_digits[i].filter(|d| *d < 12.0) {
                b.input(format!("r{n}_digits"), digits.floor());
                b.note(format!(
                    "q and p{s} lie far from the origin compared with r{s}: each is stored to about ε·|x|, so r{s} = q − p{s} keeps only about {{r{n}_digits}} significant digits of f64's 16 (the subtraction itself is exact).",
                    s = SUB[i]
                ));
            }
        }
        for i in self.immovable_named() {
            b.note(format!(
                "{} is immovable (m = ∞): it has no r and contributes nothing.",
                self.name(i)
            ));
        }
        b.done()
    }

    fn unit_impulse(&self) -> Step {
        let mut b = B::new("unit_impulse", "Velocity change per unit impulse");
        let u = &self.s.unit;
        let d = self.s.frame.normal();
        b.input("d", d);
        let mut parts = Vec::new();
        for i in 0..2 {
            let n = i + 1;
            if let Some(body) = &self.problem.bodies[i] {
                b.input(format!("m{n}"), body.mass);
                parts.push(format!("1/{{m{n}}}"));
            } else if self.lesson.slots(self.k)[i].is_some() {
                parts.push("1/∞".to_string());
            }
        }
        b.value("linear", u.linear);
        b.f("Δṗ_d", "Σ 1/mᵢ", Some(&parts.join(" + ")), Some("linear"));
        let mut total_parts = vec!["{linear}".to_string()];
        for i in self.movable() {
            let n = i + 1;
            let s = SUB[i];
            let r = u.bodies[i].as_ref().expect("movable");
            let def = &self.lesson.bodies[self.lesson.slots(self.k)[i].expect("slot")];
            b.input(format!("r{n}"), self.s.frame.r[i].unwrap_or_default());
            if let Some(t) = def.inertia {
                b.value(format!("inertia{n}"), t);
            }
            if let Some(t) = def.shape_inertia {
                b.value(format!("shape_inertia{n}"), t);
            }
            b.value(format!("inverse_inertia_world{n}"), r.inverse_inertia_world);
            b.value(format!("torque{n}"), r.torque_per_unit_impulse);
            b.value(format!("rotation{n}"), r.rotation_per_unit_impulse);
            b.value(format!("velocity{n}"), r.velocity_per_unit_impulse);
            b.value(format!("angular{n}"), r.angular);
            b.f(
                &format!("u{s}"),
                &format!("r{s} × d̂"),
                Some(&format!("{{r{n}}} × {{d}}")),
                Some(&format!("torque{n}")),
            );
            b.f(
                &format!("Δθ̇{s}"),
                &format!("I{s}⁻¹ u{s}"),
                Some(&format!("{{inverse_inertia_world{n}}} {{torque{n}}}")),
                Some(&format!("rotation{n}")),
            );
            b.f(
                &format!("Δq̇{s}"),
                &format!("Δθ̇{s} × r{s}"),
                Some(&format!("{{rotation{n}}} × {{r{n}}}")),
                Some(&format!("velocity{n}")),
            );
            b.f(
                &format!("Δq̇_d{s}"),
                &format!("Δq̇{s} · d̂"),
                Some(&format!("{{velocity{n}}} · {{d}}")),
                Some(&format!("angular{n}")),
            );
            total_parts.push(format!("{{angular{n}}}"));
            if through_centre(&self.s.frame.r[i].unwrap_or_default(), &d) {
                b.note(format!(
                    "For {} the normal passes through the centre of mass (r × d̂ ≈ 0), so the angular term is zero: only the linear term resists the impulse.",
                    self.name(i)
                ));
            }
        }
        b.value("total", u.total);
        b.f(
            "Δq̇_t",
            "Δṗ_d + Σ Δq̇_dᵢ",
            Some(&total_parts.join(" + ")),
            Some("total"),
        );
        for i in self.immovable_named() {
            b.note(format!(
                "{} is immovable: 1/m = 0 and I⁻¹ = 0, so it adds nothing.",
                self.name(i)
            ));
        }
        if let Some(m) = u.matrix {
            for i in self.movable() {
                let n = i + 1;
                let r = u.bodies[i].as_ref().expect("movable");
                let s = SUB[i];
                b.value(format!("skew_r{n}"), r.skew_r);
                b.f(&format!("[r{s}]×"), "", None, Some(&format!("skew_r{n}")));
                if let Some(a) = r.angular_matrix_world {
                    b.value(format!("angular_matrix_world{n}"), a);
                    b.f(
                        &format!("−[r{s}]× I{s}⁻¹ [r{s}]×"),
                        "",
                        Some(&format!(
                            "−{{skew_r{n}}} {{inverse_inertia_world{n}}} {{skew_r{n}}}"
                        )),
                        Some(&format!("angular_matrix_world{n}")),
                    );
                }
            }
            b.value("matrix", m);
            b.f(
                "M",
                "Cᵀ (Σ −[rᵢ]× Iᵢ⁻¹ [rᵢ]×) C + (Σ 1/mᵢ) 𝟙",
                None,
                Some("matrix"),
            );
            b.note("With friction all three contact directions matter: M maps an impulse in contact coordinates to the velocity change it causes. M[0][0] equals Δq̇_t.");
            b.note("The lecture writes M_C→W (…) M_C→Wᵀ; converting a world matrix into contact space takes Cᵀ (…) C (as the reference code does).");
        }
        b.done()
    }

    fn desired(&self) -> Step {
        let mut b = B::new("desired_delta_velocity", "Desired change in velocity");
        let dv = &self.s.desired;
        let d = self.s.frame.normal();
        b.input("d", d);
        let mut diff = Vec::new();
        for i in self.movable() {
            let n = i + 1;
            let s = SUB[i];
            let body = self.body(i);
            b.input(format!("r{n}"), self.s.frame.r[i].unwrap_or_default());
            b.input(format!("v{n}"), body.velocity);
            b.input(format!("w{n}"), body.angular_velocity);
            let pv = dv.point_velocity[i].unwrap_or_default();
            b.value(format!("point_velocity{n}"), pv);
            b.value(format!("normal_velocity{n}"), pv.dot(&d));
            b.f(
                &format!("q̇{s}"),
                &format!("ω{s} × r{s} + v{s}"),
                Some(&format!("{{w{n}}} × {{r{n}}} + {{v{n}}}")),
                Some(&format!("point_velocity{n}")),
            );
            b.f(
                &format!("q̇{s} · d̂"),
                "",
                Some(&format!("{{point_velocity{n}}} · {{d}}")),
                Some(&format!("normal_velocity{n}")),
            );
            diff.push(format!("{{point_velocity{n}}}"));
        }
        b.value("contact_velocity", dv.contact_velocity);
        b.value("separating_velocity", dv.separating());
        b.value("closing_velocity", -dv.separating());
        let world = if diff.len() == 2 {
            format!("Cᵀ ({} − {})", diff[0], diff[1])
        } else if self.movable() == vec![1] {
            format!("Cᵀ (−{})", diff[0])
        } else {
            format!("Cᵀ {}", diff[0])
        };
        b.f(
            "v_c",
            "Cᵀ (q̇₁ − q̇₂)",
            Some(&world),
            Some("contact_velocity"),
        );
        b.f("v_s", "v_c · x̂", None, Some("separating_velocity"));
        b.input("c_given", dv.restitution_given);
        b.value("restitution", dv.restitution);
        b.value("velocity_from_acceleration", dv.velocity_from_acceleration);
        if dv.velocity_from_acceleration != 0.0 {
            let mut acc = Vec::new();
            for i in self.movable() {
                let n = i + 1;
                b.input(format!("a{n}"), self.body(i).acceleration);
                acc.push(format!("{}{{a{n}}}", if i == 1 { "− " } else { "" }));
            }
            b.input("duration", self.problem.contact.settings.duration);
            b.f(
                "v_acc",
                "(a₁ − a₂)·d̂ Δt",
                Some(&format!("({})·{{d}} × {{duration}}", acc.join(" "))),
                Some("velocity_from_acceleration"),
            );
            b.f("Δv", "−v_acc − (1 + c)(v_s − v_acc)", Some("−{velocity_from_acceleration} − (1 + {restitution})({separating_velocity} − {velocity_from_acceleration})"), Some("desired"));
            b.note("Remove accelerated velocity: the velocity last frame's acceleration built up ({velocity_from_acceleration}) is not bounced back, so resting contacts do not vibrate. (This is the lecture's form; −v_s − c(v_s − v_acc), the reference code's, is the same number.)");
        } else {
            b.f(
                "Δv",
                "−(1 + c) v_s",
                Some("−(1 + {restitution})({separating_velocity})"),
                Some("desired"),
            );
        }
        b.value("desired", dv.desired);
        if dv.restitution_limited {
            b.input(
                "velocity_limit",
                self.problem.contact.settings.velocity_limit,
            );
            b.note("The closing speed |v_s| is below velocity_limit ({velocity_limit}), so restitution is forced from {c_given} to 0: a slow contact does not bounce.");
        }
        if dv.separating() < 0.0 {
            b.note("v_s < 0: the contact points are closing at {closing_velocity}.");
        } else {
            b.note("v_s ≥ 0: the contact points are separating or at rest; no impulse is needed.");
        }
        let (vy, vz) = (dv.contact_velocity.y, dv.contact_velocity.z);
        if crate::physics::scale::stable_hypot(vy, vz)
            > 1e-12 * crate::physics::scale::stable_norm(&dv.contact_velocity)
        {
            b.note("The y and z components of v_c are sliding velocity in the contact plane; only friction acts on them.");
        }
        b.done()
    }

    fn impulse(&self) -> Step {
        let mut b = B::new("impulse", "Impulse");
        let Some(g) = &self.s.impulse else {
            return b.skipped(skip_reason(Skip::Separating));
        };
        let d = self.s.frame.normal();
        b.input("d", d);
        b.input("desired", self.s.desired.desired);
        b.input("total", self.s.unit.total);
        b.input("contact_to_world", self.s.frame.contact_to_world);
        b.value("impulse_contact", g.impulse_contact);
        b.value("impulse_world", g.impulse_world);
        match &g.solve {
            None => {
                b.input("g", g.impulse_contact.x);
                b.f("g", "Δv / Δq̇_t", Some("{desired} / {total}"), Some("g"));
                b.f("g_contact", "(g, 0, 0)", None, Some("impulse_contact"));
                b.f(
                    "g_world",
                    "C g_contact = g d̂",
                    Some("{g} × {d}"),
                    Some("impulse_world"),
                );
            }
            Some(solve) => {
                b.input("matrix", self.s.unit.matrix.unwrap_or_default());
                b.input("rhs", solve.rhs);
                b.value("condition_number", solve.condition_number);
                b.f(
                    "g_contact",
                    "M⁻¹ (Δv, −v_y, −v_z)",
                    Some("{matrix}⁻¹ {rhs}"),
                    Some("impulse_contact"),
                );
                b.f(
                    "g_world",
                    "C g_contact",
                    Some("{contact_to_world} {impulse_contact}"),
                    Some("impulse_world"),
                );
                b.note("This is the sticking impulse: it meets the normal target and removes all sliding. The friction clamp decides whether friction can supply it.");
                b.note("κ(M) = {condition_number}: about log₁₀ κ of the 16 significant digits of f64 are lost solving for g.");
                if solve.ill_conditioned {
                    b.note("ILL-CONDITIONED: κ(M) · ε > 10⁻³, so fewer than three digits of g can be trusted (a huge mass with a tiny inertia, or the reverse).");
                }
                if solve.singular {
                    b.note("SINGULAR: M could not be factorised, or κ(M) · ε ≥ 1 so no digit of g would be right; the frictionless impulse Δv / Δq̇_t is used instead.");
                } else if solve.used_lu {
                    b.note(
                        "M is not numerically positive-definite (Cholesky failed); LU was used.",
                    );
                }
            }
        }
        b.value("closed_form_j", g.closed_form_j);
        b.value(
            "closed_form_relative_difference",
            g.closed_form_relative_difference,
        );
        b.f(
            "j",
            "−(1 + c)(v_rel · n) / (Σ 1/mᵢ + Σ (rᵢ × n)ᵀ Iᵢ⁻¹ (rᵢ × n))",
            None,
            Some("closed_form_j"),
        );
        if g.solve.is_some() {
            b.note("For comparison, without friction the companion lectures' closed form gives j = {closed_form_j} along the normal.");
        } else if self.s.desired.velocity_from_acceleration == 0.0 {
            b.note("The companion lectures' closed form j = {closed_form_j} agrees with Δv / Δq̇_t to a relative {closed_form_relative_difference}: the same number by a different route ((r × n)ᵀ I⁻¹ (r × n) = ((I⁻¹(r × n)) × r) · n).");
        } else {
            b.note("The closed form j = {closed_form_j} has no acceleration compensation, so it differs from Δv / Δq̇_t here (relative {closed_form_relative_difference}).");
        }
        b.done()
    }

    fn friction(&self) -> Step {
        let mut b = B::new("friction_clamp", "Friction clamp");
        if let Some(skip) = self.s.skip("friction_clamp") {
            return b.skipped(skip_reason(skip));
        }
        let f = self.s.friction.as_ref().expect("friction ran");
        let g = self.s.impulse.as_ref().expect("impulse ran");
        let c = &self.problem.contact;
        b.input("mu_s", c.static_friction);
        b.input("mu_d", c.dynamic_friction);
        b.input("sticking", g.impulse_contact);
        b.input("sticking_normal", g.impulse_contact.x);
        b.input("desired", self.s.desired.desired);
        b.input("contact_to_world", self.s.frame.contact_to_world);
        let regime = match f.regime {
            FrictionRegime::Static => "static",
            FrictionRegime::Dynamic => "dynamic",
        };
        b.value("model", f.model.name());
        b.value("regime", regime);
        let (decided_by, sized_by) = match (f.model, f.regime) {
            (FrictionModel::KineticDirection, _) => ("none (always sliding)", "dynamic_friction"),
            (_, FrictionRegime::Static) => ("static_friction", "none (the sticking impulse)"),
            (_, FrictionRegime::Dynamic) => ("static_friction", "dynamic_friction"),
        };
        b.value("decided_by", decided_by);
        b.value("sized_by", sized_by);
        b.value("planar", f.planar);
        b.value("limit", f.limit);
        b.value("impulse_contact", f.impulse_contact);
        b.value("impulse_world", f.impulse_world);
        match f.model {
            FrictionModel::Millington => {
                b.f("|g_planar|", "√(g_y² + g_z²)", None, Some("planar"));
                b.f(
                    "limit",
                    "μ_s g_n",
                    Some("{mu_s} × {sticking_normal}"),
                    Some("limit"),
                );
                if f.regime == FrictionRegime::Static {
                    b.note("|g_planar| ≤ μ_s g_n: static friction can supply the sticking impulse, so the contact sticks and the impulse is unchanged. μ_s decided the regime.");
                } else if f.issue == Some(FrictionIssue::Jamming) {
                    b.note("JAMMING: M₀₀ + μ_d(M₀₁u_y + M₀₂u_z) ≤ 0, friction would need a negative normal impulse; the frictionless impulse is used instead.");
                } else {
                    b.input("matrix", self.s.unit.matrix.unwrap_or_default());
                    b.value("direction", f.direction);
                    b.value("normal_per_unit", f.normal_per_unit);
                    b.value("normal_impulse", f.impulse_contact.x);
                    b.f("u", "(0, g_y, g_z) / |g_planar|", None, Some("direction"));
                    b.f(
                        "M₀₀ + μ_d (M₀₁ u_y + M₀₂ u_z)",
                        "",
                        None,
                        Some("normal_per_unit"),
                    );
                    b.f(
                        "g_n",
                        "Δv / (M₀₀ + μ_d (M₀₁ u_y + M₀₂ u_z))",
                        Some("{desired} / {normal_per_unit}"),
                        Some("normal_impulse"),
                    );
                    b.f(
                        "g",
                        "(g_n, μ_d g_n u_y, μ_d g_n u_z)",
                        None,
                        Some("impulse_contact"),
                    );
                    b.note("|g_planar| > μ_s g_n: the contact slides. μ_s decided the regime; μ_d = {mu_d} sizes the tangential impulse μ_d g_n along the sticking impulse's direction u, and g_n is recomputed so the normal velocity target Δv still holds.");
                }
            }
            FrictionModel::VelocityScaling => {
                b.f("|v_planar|", "√(v_y² + v_z²)", None, Some("planar"));
                b.f("limit", "v_c μ_s", None, Some("limit"));
                if f.regime == FrictionRegime::Static {
                    b.note("Seed 004's model: |v_planar| ≤ v_c μ_s, so all planar velocity is removed (the sticking impulse). Here planar and limit are velocities, not impulses.");
                } else {
                    b.f(
                        "g",
                        "M⁻¹ (Δv, −μ_d v_y, −μ_d v_z)",
                        None,
                        Some("impulse_contact"),
                    );
                    b.note("Seed 004's model: |v_planar| > v_c μ_s, so the planar velocity is reduced by μ_d·v_planar rather than removed. This is not Coulomb's law: the impulse may leave the friction cone.");
                }
            }
            FrictionModel::KineticDirection => {
                b.f("g", "j (n + μ_k t)", None, Some("impulse_world"));
                if f.issue == Some(FrictionIssue::UndefinedDirection) {
                    b.note("Seeds 002/003's model: t = (n × v_rel) × n / |…| is undefined because nothing slides (v_rel ∥ n); the model applies no friction impulse.");
                } else {
                    b.note("Seeds 002/003's model: friction μ_k j acts against the sliding direction t, whatever the sliding speed, so it may reverse the slip. The seeds write t along the sliding velocity; friction must oppose it, so contact-lab uses −t.");
                }
            }
        }
        b.f(
            "g_world",
            "C g_contact",
            Some("{contact_to_world} {impulse_contact}"),
            Some("impulse_world"),
        );
        b.done()
    }

    fn apply(&self) -> Step {
        let mut b = B::new("apply_impulse", "Applying the impulse");
        let Some(a) = &self.s.applied else {
            return b.skipped(skip_reason(Skip::Separating));
        };
        for i in self.movable() {
            let n = i + 1;
            let s = SUB[i];
            let body = self.body(i);
            let c = a.bodies[i].as_ref().expect("movable");
            b.input(format!("m{n}"), body.mass);
            b.input(format!("r{n}"), self.s.frame.r[i].unwrap_or_default());
            b.input(format!("v{n}_before"), body.velocity);
            b.input(format!("w{n}_before"), body.angular_velocity);
            b.input(
                format!("inverse_inertia_world{n}"),
                body.inverse_inertia_world(),
            );
            b.value(format!("impulse{n}"), c.impulse);
            b.value(format!("impulsive_torque{n}"), c.impulsive_torque);
            b.value(format!("dv{n}"), c.dv);
            b.value(format!("dw{n}"), c.dw);
            b.value(format!("v{n}"), c.v);
            b.value(format!("w{n}"), c.w);
            b.value(
                format!("dw{n}_degrees_per_second"),
                crate::physics::scale::stable_norm(&c.dw).to_degrees(),
            );
            let g = if i == 0 { "g" } else { "−g" };
            b.f(
                &format!("Δṗ{s}"),
                &format!("{g} / m{s}"),
                Some(&format!("{{impulse{n}}} / {{m{n}}}")),
                Some(&format!("dv{n}")),
            );
            b.f(
                &format!("u{s}"),
                &format!("r{s} × {}", if i == 0 { "g" } else { "(−g)" }),
                Some(&format!("{{r{n}}} × {{impulse{n}}}")),
                Some(&format!("impulsive_torque{n}")),
            );
            b.f(
                &format!("Δθ̇{s}"),
                &format!("I{s}⁻¹ u{s}"),
                Some(&format!(
                    "{{inverse_inertia_world{n}}} {{impulsive_torque{n}}}"
                )),
                Some(&format!("dw{n}")),
            );
            b.f(
                &format!("v{s}′"),
                &format!("v{s} + Δṗ{s}"),
                Some(&format!("{{v{n}_before}} + {{dv{n}}}")),
                Some(&format!("v{n}")),
            );
            b.f(
                &format!("ω{s}′"),
                &format!("ω{s} + Δθ̇{s}"),
                Some(&format!("{{w{n}_before}} + {{dw{n}}}")),
                Some(&format!("w{n}")),
            );
            // The impulse (with friction, not only its normal part) passes
            // through the centre: any spin left is the data's rounding.
            let rounding = through_centre(
                &self.s.frame.r[i].unwrap_or_default(),
                &c.impulse.normalize(),
            );
            if rounding && c.dw != Vector3::zeros() {
                b.note(format!(
                    "{}'s spin changes by only {{dw{n}_degrees_per_second}} °/s: the impulse passes through its centre to within the data's rounding, so this is what the rounding leaves, not a real spin-up.",
                    self.name(i)
                ));
            } else if let Some((axis, ccw)) = about_one_axis(&c.dw) {
                b.note(format!(
                    "{}'s spin changes by |Δθ̇{s}| = {{dw{n}_degrees_per_second}} °/s, {} about the {axis}-axis (seen from +{axis}).",
                    self.name(i),
                    sense(ccw)
                ));
            }
        }
        if self.movable().len() == 2 {
            b.note("Both bodies receive the same impulse in opposite directions: body 2 gets −g.");
        }
        b.done()
    }

    fn projection(&self) -> Step {
        let mut b = B::new("nonlinear_projection", "Resolving interpenetration");
        let Some(p) = &self.s.projection else {
            return b.skipped(skip_reason(Skip::NoPenetration));
        };
        let settings = &self.problem.contact.settings;
        b.input("d", self.s.frame.normal());
        b.input("d_pen", self.problem.contact.penetration);
        b.input("relaxation", settings.relaxation);
        b.input("angular_limit_setting", settings.angular_limit);
        b.value("method", p.method.name());
        b.value("resolved_depth", p.resolved_depth);
        if settings.relaxation != 1.0 {
            b.f(
                "d",
                "d_pen × relaxation",
                Some("{d_pen} × {relaxation}"),
                Some("resolved_depth"),
            );
        }
        let mut total = Vec::new();
        for i in self.movable() {
            let n = i + 1;
            let s = SUB[i];
            let m = p.bodies[i].as_ref().expect("movable");
            b.input(format!("m{n}"), self.body(i).mass);
            b.input(format!("r{n}"), self.s.frame.r[i].unwrap_or_default());
            b.value(format!("linear_inertia{n}"), m.linear_inertia);
            b.value(format!("angular_inertia{n}"), m.angular_inertia);
            b.f(
                &format!("I_l{s}"),
                &format!("1/m{s}"),
                Some(&format!("1/{{m{n}}}")),
                Some(&format!("linear_inertia{n}")),
            );
            if p.method == ProjectionMethod::Nonlinear {
                b.f(
                    &format!("I_a{s}"),
                    &format!("((I{s}⁻¹(r{s} × d̂)) × r{s}) · d̂"),
                    None,
                    Some(&format!("angular_inertia{n}")),
                );
            }
            total.push(format!("{{linear_inertia{n}}} + {{angular_inertia{n}}}"));
        }
        b.value("total_inertia", p.total_inertia);
        b.f(
            "I_t",
            "Σ (I_lᵢ + I_aᵢ)",
            Some(&total.join(" + ")),
            Some("total_inertia"),
        );
        let depth = if settings.relaxation != 1.0 {
            "{resolved_depth}"
        } else {
            "{d_pen}"
        };
        for i in self.movable() {
            let n = i + 1;
            let s = SUB[i];
            let sign = if i == 0 { "" } else { "−" };
            let m = p.bodies[i].as_ref().expect("movable");
            b.input(format!("p{n}"), self.body(i).position);
            b.value(format!("linear_move{n}"), m.linear_move);
            b.value(format!("angular_move{n}"), m.angular_move);
            if m.angular_limit.is_finite() {
                b.value(format!("angular_limit{n}"), m.angular_limit);
            } else {
                b.value(format!("angular_limit{n}"), "none");
            }
            b.input(format!("r_perp_length{n}"), m.r_perp_length);
            b.value(format!("linear_change{n}"), m.linear_change);
            b.value(format!("rotation_per_unit{n}"), m.rotation_per_unit);
            b.value(format!("angular_change{n}"), m.angular_change);
            b.value(format!("position{n}"), m.position);
            let e = format!("(−1)^({n}+1)");
            // Before the limit; when it acts, the clamped moves follow below.
            b.input(
                format!("angular_move_unlimited{n}"),
                m.angular_move_unlimited,
            );
            b.input(format!("linear_move_unlimited{n}"), m.linear_move_unlimited);
            let (lin, ang) = if m.limited {
                (
                    format!("linear_move_unlimited{n}"),
                    format!("angular_move_unlimited{n}"),
                )
            } else {
                (format!("linear_move{n}"), format!("angular_move{n}"))
            };
            b.f(
                &format!("Δ_l{s}"),
                &format!("{e} d_pen I_l{s} / I_t"),
                Some(&format!(
                    "{sign}{depth} × {{linear_inertia{n}}} / {{total_inertia}}"
                )),
                Some(&lin),
            );
            b.f(
                &format!("Δ_a{s}"),
                &format!("{e} d_pen I_a{s} / I_t"),
                Some(&format!(
                    "{sign}{depth} × {{angular_inertia{n}}} / {{total_inertia}}"
                )),
                Some(&ang),
            );
            if !m.angular_limit.is_finite() {
                b.note("angular_limit = inf: the angular move is not limited.");
            } else {
                b.f(
                    &format!("limit{s}"),
                    &format!("angular_limit · |r{s} − (r{s}·d̂)d̂|"),
                    Some(&format!("{{angular_limit_setting}} × {{r_perp_length{n}}}")),
                    Some(&format!("angular_limit{n}")),
                );
            }
            if m.limited {
                b.f(
                    &format!("Δ_a{s} (limited)"),
                    &format!("±limit{s}"),
                    None,
                    Some(&format!("angular_move{n}")),
                );
                b.f(
                    &format!("Δ_l{s} (limited)"),
                    &format!("Δ_l{s} + (Δ_a{s} − Δ_a{s} (limited))"),
                    Some(&format!("{{linear_move_unlimited{n}}} + ({{angular_move_unlimited{n}}} − {{angular_move{n}}})")),
                    Some(&format!("linear_move{n}")),
                );
                b.note(format!(
                    "Excessive rotation: {}'s angular move {{angular_move_unlimited{n}}} exceeds the limit {{angular_limit{n}}}; it is cut to the limit and the excess moves to the linear share ({{linear_move_unlimited{n}}} → {{linear_move{n}}}).",
                    self.name(i)
                ));
            }
            b.f(
                &format!("Δp{s}"),
                &format!("Δ_l{s} d̂"),
                Some(&format!("{{linear_move{n}}} × {{d}}")),
                Some(&format!("linear_change{n}")),
            );
            b.f(
                &format!("Δθ{s}"),
                &format!("I{s}⁻¹(r{s} × d̂) (Δ_a{s} / I_a{s})"),
                Some(&format!(
                    "{{rotation_per_unit{n}}} × ({{angular_move{n}}} / {{angular_inertia{n}}})"
                )),
                Some(&format!("angular_change{n}")),
            );
            b.f(
                &format!("p{s}′"),
                &format!("p{s} + Δ_l{s} d̂"),
                Some(&format!("{{p{n}}} + {{linear_change{n}}}")),
                Some(&format!("position{n}")),
            );
            let d = self.s.frame.normal();
            if through_centre(&self.s.frame.r[i].unwrap_or_default(), &d)
                && p.method == ProjectionMethod::Nonlinear
            {
                b.note(format!(
                    "{}'s contact arm lies along the normal (r × d̂ ≈ 0): its angular inertia is (all but) zero, so it (all but) only translates.",
                    self.name(i)
                ));
            }
        }
        if p.method == ProjectionMethod::Linear {
            b.note("Linear projection: each body moves along the normal in proportion to its inverse mass; nothing rotates.");
        }
        b.note("The moves of all bodies add up to the depth resolved: Σ |Δ_l| + |Δ_a| = d_pen × relaxation.");
        b.done()
    }

    fn orientation(&self) -> Step {
        let mut b = B::new("orientation_update", "Orientation update");
        let Some(o) = &self.s.orientation else {
            return match self.s.skip("orientation_update") {
                Some(Skip::NoPenetration) => {
                    b.skipped("no penetration (d_pen ≤ 0): no projection, so no body turns")
                }
                other => b.skipped(skip_reason(other.unwrap_or(Skip::NoRotation))),
            };
        };
        for i in self.movable() {
            let Some(u) = &o.bodies[i] else { continue };
            let n = i + 1;
            let s = SUB[i];
            b.input(format!("before{n}"), u.before);
            b.input(format!("rotation{n}"), u.rotation);
            b.value(format!("orientation{n}_unnormalised"), u.unnormalised);
            b.value(format!("orientation{n}"), u.normalised);
            b.value(format!("rotation_degrees{n}"), u.angle_degrees);
            b.value(format!("rotation_axis{n}"), u.axis);
            b.value(
                format!("rotation_vector_degrees{n}"),
                u.rotation_vector_degrees,
            );
            b.value(format!("euler_zyx_degrees{n}"), u.euler_zyx_degrees);
            b.f(
                &format!("θ{s}′"),
                &format!("θ{s} + ½ [0, Δθ{s}] θ{s}"),
                Some(&format!(
                    "{{before{n}}} + ½ [0, {{rotation{n}}}] {{before{n}}}"
                )),
                Some(&format!("orientation{n}_unnormalised")),
            );
            b.f(
                &format!("θ{s}′ / |θ{s}′|"),
                "",
                None,
                Some(&format!("orientation{n}")),
            );
            b.f(
                "angle",
                "2 atan2(|v|, w) of θ′ θ⁻¹",
                None,
                Some(&format!("rotation_degrees{n}")),
            );
            let name = self.name(i);
            if let Some((axis, ccw)) = about_one_axis(&u.rotation) {
                let signed = if ccw {
                    u.angle_degrees
                } else {
                    -u.angle_degrees
                };
                b.value(format!("rotation_signed_degrees{n}"), signed);
                b.value(format!("rotation_world_axis{n}"), axis.to_string().as_str());
            }
            let rounding = through_centre(
                &self.s.frame.r[i].unwrap_or_default(),
                &self.s.frame.normal(),
            );
            match about_one_axis(&u.rotation) {
                _ if rounding => b.note(format!(
                    "{name} turns only {{rotation_degrees{n}}}°: its contact arm lies along the normal to within the data's rounding, so this is what the rounding leaves."
                )),
                Some((axis, ccw)) => b.note(format!(
                    "{name} turns {{rotation_degrees{n}}}° {} about the {axis}-axis (seen from +{axis}); |Δθ| = {{rotation_vector_degrees{n}}}° is the small-angle estimate of the same turn.",
                    sense(ccw)
                )),
                None => b.note(format!("{name} turns {{rotation_degrees{n}}}° about the axis {{rotation_axis{n}}}.")),
            }
            b.note(format!("Euler angles of the new orientation, intrinsic z-y′-x″ (yaw, pitch, roll): {{euler_zyx_degrees{n}}}°."));
        }
        b.note("Adding ½[0, Δθ]θ is a first-order step: the sum is not unit length, so it is normalised; the turn it represents is slightly smaller than |Δθ|.");
        b.done()
    }

    fn checks(&self) -> Step {
        let mut b = B::new("checks", "Checks");
        for item in &self.s.checks.items {
            for (name, v) in &item.values {
                b.value(name.clone(), *v);
            }
        }
        if self.s.checks.get(CheckKind::Restitution).is_some() {
            b.input("desired", self.s.desired.desired);
            b.f("v_s′", "(q̇₁′ − q̇₂′) · d̂", None, Some("separating_velocity"));
            b.f(
                "target",
                "v_s + Δv",
                Some("{separating_velocity_before} + {desired}"),
                Some("separating_velocity_expected"),
            );
        }
        // Why each check came out as it did, where a cause is known.
        b.input(
            "velocity_from_acceleration",
            self.s.desired.velocity_from_acceleration,
        );
        let friction = self.problem.contact.has_friction();
        for item in &self.s.checks.items {
            let Some(cause) = &item.cause else { continue };
            if let Some(d) = super::causes::describe(item.kind, cause, friction) {
                for (name, v) in d.inputs {
                    b.input(name, v);
                }
                b.note(d.note);
            }
        }
        if self
            .s
            .checks
            .get(CheckKind::Slip)
            .is_some_and(|c| c.passed.is_none() && c.cause.is_none())
        {
            b.note("The slip speed rose ({slip_speed_before} → {slip_speed_after}) while sliding: the normal impulse itself drives the contact point sideways (M₀₁, M₀₂ ≠ 0), more than friction capped at μ g_n can take away. This is Coulomb friction working as intended, not an error.");
        }
        if self.s.checks.get(CheckKind::ResidualPenetration).is_some() {
            b.f(
                "residual",
                "d_pen − Σ (−1)^(i+1) (qᵢ′ − q) · d̂",
                Some("{depth_to_resolve} − {separation_gained}"),
                Some("residual_penetration"),
            );
            b.note("Residual penetration = depth to resolve − separation actually gained when each body's contact point is carried by its finite move (new position and normalised rotation). It measures how far the linearised estimate is off.");
        }
        b.done()
    }

    fn verdicts(&self) -> Vec<Verdict> {
        self.s
            .checks
            .items
            .iter()
            .map(|item| {
                let (label, detail) = match item.kind {
                    CheckKind::LinearMomentum => (
                        "linear momentum conserved".to_string(),
                        "error {linear_momentum_error}".to_string(),
                    ),
                    CheckKind::AngularMomentum(i) => (
                        format!("angular momentum of {} about q conserved", self.name(i)),
                        format!("error {{angular_momentum_error{}}}", i + 1),
                    ),
                    CheckKind::Restitution => (
                        "separating velocity meets the target".to_string(),
                        "v_s′ = {separating_velocity}, target {separating_velocity_expected}"
                            .to_string(),
                    ),
                    CheckKind::Energy => (
                        "kinetic energy does not rise".to_string(),
                        "{energy_before} → {energy_after}".to_string(),
                    ),
                    CheckKind::FrictionCone => (
                        "impulse inside the friction cone".to_string(),
                        "g_n = {normal_impulse}, |g_t| = {tangential_impulse} ≤ {cone_limit}"
                            .to_string(),
                    ),
                    CheckKind::Slip => (
                        "slip speed does not rise".to_string(),
                        "{slip_speed_before} → {slip_speed_after}".to_string(),
                    ),
                    CheckKind::ResidualPenetration => (
                        "penetration left after the finite move".to_string(),
                        "{residual_penetration} of {depth_to_resolve}".to_string(),
                    ),
                    CheckKind::UnitQuaternion(i) => (
                        format!("{}'s orientation is a unit quaternion", self.name(i)),
                        format!("| |θ′| − 1 | = {{orientation_norm_error{}}}", i + 1),
                    ),
                };
                Verdict {
                    label,
                    passed: item.passed,
                    detail,
                }
            })
            .collect()
    }
}
