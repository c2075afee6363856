//! The impact integration of a contact on its own ([`exact_impact`]): its
//! one-shot impulse solved first (`physics::solve`, which itself runs
//! [`exact_impact_beside`] for the `exact_impact` stage), then integrated
//! beside it.

use nalgebra::Vector3;

use super::contact::{exact_impact_beside, ExactImpact};
use super::{ExactError, RestitutionLaw, Tolerance};
use crate::physics::solve::solve_stages;
use crate::physics::{Problem, Real};

/// Integrates the impact of `problem`'s contact under `law`, with the default tolerance.
///
/// Restitution is the contact's given restitution applied to the actual
/// contact velocity u0: no velocity limit and no acceleration compensation
/// (the one-shot beside it keeps both, so the two differ where they act).
/// Friction is Coulomb's with μ_s and μ_d whatever the contact's friction
/// model; without friction K is still the full 3×3 matrix.
pub fn exact_impact<T: Real>(
    problem: &Problem<T>,
    law: RestitutionLaw,
) -> Result<ExactImpact<T>, ExactError> {
    exact_impact_with(problem, law, Tolerance::default())
}

/// [`exact_impact`] with a chosen tolerance and budget.
pub fn exact_impact_with<T: Real>(
    problem: &Problem<T>,
    law: RestitutionLaw,
    tolerance: Tolerance<T>,
) -> Result<ExactImpact<T>, ExactError> {
    let mut one_shot_problem = problem.clone();
    one_shot_problem.contact.settings.exact = None;
    let one_shot_world = solve_stages(&one_shot_problem)
        .final_impulse_world()
        .unwrap_or_else(Vector3::zeros);
    exact_impact_beside(problem, law, tolerance, one_shot_world)
}
