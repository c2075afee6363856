//! Stage 5: the friction clamp.
//!
//! Millington (lecture procedure, reference engine): if `|g_planar| ≤ μ_s g_n`
//! the contact sticks; otherwise it slides, the tangential impulse becomes
//! `μ_d g_n` along the sticking impulse's direction and `g_n` is recomputed so
//! the normal velocity target still holds. The companion lectures' other models live here too.

use nalgebra::Vector3;

use super::impulse::FactoredMatrix;
use super::{ContactFrame, DesiredVelocity, Impulse, MatrixSolve, UnitImpulse};
use crate::physics::scale::stable_hypot;
use crate::physics::{FrictionModel, Problem, Real};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrictionRegime {
    Static,
    Dynamic,
}

/// Why the clamp could not do what its model asks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrictionIssue {
    /// Kinetic-direction model: no sliding, so the tangent `t` is undefined.
    UndefinedDirection,
    /// Millington dynamic case: `M₀₀ + μ_d(M₀₁u_y + M₀₂u_z) ≤ 0`, friction would
    /// need a negative normal impulse (jamming); the frictionless impulse is used.
    Jamming,
}

#[derive(Debug, Clone, PartialEq)]
pub struct FrictionClamp<T: Real> {
    pub model: FrictionModel,
    pub regime: FrictionRegime,
    /// Millington: |g_planar| of the sticking impulse. Velocity-scaling: |v_planar|
    /// (a velocity). Kinetic-direction: μ_k j.
    pub planar: T,
    /// The static limit the regime was decided against (μ_s g_n, or v_c μ_s).
    pub limit: T,
    /// Coefficient that sized the tangential impulse (μ_d when sliding).
    pub sized_by: Option<T>,
    /// Unit slide direction in contact space `(0, u_y, u_z)` (dynamic cases).
    pub direction: Vector3<T>,
    /// Millington dynamic: `M₀₀ + μ_d (M₀₁ u_y + M₀₂ u_z)`, velocity per unit normal impulse.
    pub normal_per_unit: T,
    pub impulse_contact: Vector3<T>,
    pub impulse_world: Vector3<T>,
    /// Present when the dynamic case re-solved the 3×3 system (velocity-scaling).
    pub solve: Option<MatrixSolve<T>>,
    pub issue: Option<FrictionIssue>,
}

/// What the clamp needs, by value: the resolver fills it from its bookkeeping,
/// the stage from the problem and the earlier stages.
#[derive(Debug, Clone)]
pub struct ClampInputs<'a, T: Real> {
    pub model: FrictionModel,
    pub static_friction: T,
    pub dynamic_friction: T,
    /// The impulse before the clamp (contact space).
    pub impulse_contact: Vector3<T>,
    /// Contact velocity (contact space).
    pub contact_velocity: Vector3<T>,
    /// Desired Δv along the normal.
    pub desired: T,
    /// `Δq̇_t`, for the frictionless fallback.
    pub total: T,
    /// The 3×3 contact-space matrix `M` (built with friction), factored.
    pub matrix: Option<&'a FactoredMatrix<T>>,
    /// The normal impulse `j` the kinetic-direction model scales by.
    pub closed_form_j: T,
    pub contact_to_world: &'a nalgebra::Matrix3<T>,
}

pub fn friction_clamp<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    unit: &UnitImpulse<T>,
    desired: &DesiredVelocity<T>,
    impulse: &Impulse<T>,
) -> FrictionClamp<T> {
    let factored = unit.matrix.map(FactoredMatrix::new);
    clamp(clamp_inputs(
        problem,
        frame,
        unit,
        desired,
        impulse,
        factored.as_ref(),
    ))
}

/// [`friction_clamp`] with `M` already factored (the stage path factors it
/// once for the impulse and the clamp), written into `out` (the stage path's form:
/// [`clamp`], inlined, builds the record where it stays).
#[inline]
pub fn friction_clamp_factored_into<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    unit: &UnitImpulse<T>,
    desired: &DesiredVelocity<T>,
    impulse: &Impulse<T>,
    factored: Option<&FactoredMatrix<T>>,
    out: &mut Option<FrictionClamp<T>>,
) {
    *out = Some(clamp(clamp_inputs(
        problem, frame, unit, desired, impulse, factored,
    )));
}

/// What the clamp reads of a contact's earlier stages.
#[inline]
fn clamp_inputs<'a, T: Real>(
    problem: &Problem<T>,
    frame: &'a ContactFrame<T>,
    unit: &UnitImpulse<T>,
    desired: &DesiredVelocity<T>,
    impulse: &Impulse<T>,
    factored: Option<&'a FactoredMatrix<T>>,
) -> ClampInputs<'a, T> {
    let contact = &problem.contact;
    ClampInputs {
        model: contact.friction_model,
        static_friction: contact.static_friction,
        dynamic_friction: contact.dynamic_friction,
        impulse_contact: impulse.impulse_contact,
        contact_velocity: desired.contact_velocity,
        desired: desired.desired,
        total: unit.total,
        matrix: factored,
        closed_form_j: impulse.closed_form_j,
        contact_to_world: &frame.contact_to_world,
    }
}

/// The clamp of each friction model on an impulse (see the module comment).
#[inline]
pub fn clamp<T: Real>(input: ClampInputs<'_, T>) -> FrictionClamp<T> {
    let (mu_s, mu_d) = (input.static_friction, input.dynamic_friction);
    let g = input.impulse_contact;
    let v = input.contact_velocity;
    let mut out = FrictionClamp {
        model: input.model,
        regime: FrictionRegime::Static,
        planar: T::zero(),
        limit: T::zero(),
        sized_by: None,
        direction: Vector3::zeros(),
        normal_per_unit: T::zero(),
        impulse_contact: g,
        impulse_world: input.contact_to_world * g,
        solve: None,
        issue: None,
    };
    match input.model {
        FrictionModel::Millington => {
            out.planar = stable_hypot(g.y, g.z);
            out.limit = mu_s * g.x;
            if out.planar > out.limit {
                out.regime = FrictionRegime::Dynamic;
                out.sized_by = Some(mu_d);
                let m = input
                    .matrix
                    .map_or_else(nalgebra::Matrix3::identity, |m| m.matrix);
                let (uy, uz) = (g.y / out.planar, g.z / out.planar);
                let per_unit = m[(0, 0)] + mu_d * (m[(0, 1)] * uy + m[(0, 2)] * uz);
                out.direction = Vector3::new(T::zero(), uy, uz);
                out.normal_per_unit = per_unit;
                if per_unit > T::zero() {
                    let gn = input.desired / per_unit;
                    out.impulse_contact = Vector3::new(gn, mu_d * gn * uy, mu_d * gn * uz);
                } else {
                    out.issue = Some(FrictionIssue::Jamming);
                    out.impulse_contact =
                        Vector3::new(input.desired / input.total, T::zero(), T::zero());
                }
            }
        }
        FrictionModel::VelocityScaling => {
            out.planar = stable_hypot(v.y, v.z);
            out.limit = -v.x * mu_s;
            if out.planar > out.limit {
                out.regime = FrictionRegime::Dynamic;
                out.sized_by = Some(mu_d);
                if let Some(m) = input.matrix {
                    let rhs = Vector3::new(input.desired, -mu_d * v.y, -mu_d * v.z);
                    let (solved, solve) = m.solve(rhs);
                    if let Some(solved) = solved {
                        out.impulse_contact = solved;
                    }
                    out.solve = Some(solve);
                }
            }
        }
        FrictionModel::KineticDirection => {
            let j = input.closed_form_j;
            let slide = stable_hypot(v.y, v.z);
            out.limit = mu_d * j;
            // t is undefined when nothing slides; ε-relative test against the normal speed.
            if slide > T::default_epsilon() * (v.x.abs() + slide) && slide > T::zero() {
                out.regime = FrictionRegime::Dynamic;
                out.sized_by = Some(mu_d);
                out.planar = mu_d * j;
                out.direction = Vector3::new(T::zero(), -v.y / slide, -v.z / slide);
                out.impulse_contact =
                    Vector3::new(j, -mu_d * j * v.y / slide, -mu_d * j * v.z / slide);
            } else {
                out.issue = Some(FrictionIssue::UndefinedDirection);
                out.impulse_contact = Vector3::new(j, T::zero(), T::zero());
            }
        }
    }
    out.impulse_world = input.contact_to_world * out.impulse_contact;
    out
}
