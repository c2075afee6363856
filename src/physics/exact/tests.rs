//! Unit tests of the kernel on hand-derived planar impacts, in closed form
//! and forced through the integrator.

use nalgebra::{Matrix3, Vector2, Vector3};

use super::*;

/// A slender rod (m = 1, length 2, I = 1/3) landing on its end at 45°:
/// r = (-1/√2, -1/√2), so K_nn = K_tt = 1/m + r²/(2I) = 2.5 and
/// K_nt = -r_x r_y / I = -1.5 (planar; the out-of-plane tangent is uncoupled).
/// τ = -K_tn/K_tt = 0.6.
fn rod() -> Matrix3<f64> {
    Matrix3::new(2.5, -1.5, 0.0, -1.5, 2.5, 0.0, 0.0, 0.0, 4.0)
}

fn input(u0: Vector3<f64>, mu: f64, e: f64, law: RestitutionLaw) -> ImpactInput<f64> {
    ImpactInput {
        k: rod(),
        u0,
        static_friction: mu,
        dynamic_friction: mu,
        restitution: e,
        law,
        tolerance: Tolerance::default(),
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

fn kinds(o: &ImpactOutcome<f64>) -> Vec<(&'static str, f64)> {
    o.phases.iter().map(|p| (p.kind.name(), p.to_pn)).collect()
}

/// μ = 0.5 < τ: slip reverses. u0 = (-1, 0.55). Forward slip (s = +1):
/// du/dP_n = K(1, -μ) = (3.25, -2.75), halts at P_n = 0.55/2.75 = 0.2 with
/// u_n = -0.35. Reversed (s = -1): du/dP_n = K(1, μ) = (1.75, -0.25), so
/// compression ends at P_c = 0.2 + 0.35/1.75 = 0.4. W_c = -0.135 - 0.035 = -0.17.
/// Poisson e = 0.5: P_n = 0.6, P_t = -0.5·0.2 + 0.5·0.4 = 0.1, u = (0.35, -0.1).
/// Newton: 1.75 (P_n - 0.4) = 0.5 → P_n = 0.4 + 2/7.
/// Stronge: ½·1.75 δ² = 0.25·0.17 → P_n = 0.4 + √(0.0425/0.875).
#[test]
fn rod_slip_reverses_closed_form() {
    let u0 = Vector3::new(-1.0, 0.55, 0.0);
    let poisson = integrate(&input(u0, 0.5, 0.5, RestitutionLaw::Poisson)).unwrap();
    assert!((poisson.impulse - Vector3::new(0.6, 0.1, 0.0)).norm() < 1e-15);
    assert!((poisson.velocity - Vector3::new(0.35, -0.1, 0.0)).norm() < 1e-15);
    assert!(close(poisson.compression_pn, 0.4, 1e-15));
    assert!(close(poisson.work_compression, -0.17, 1e-15));
    // W_r = ½·1.75·0.2², W_t = -0.5·(0.55·0.2/2) - 0.5·(0.25·0.4·0.4/2) = -0.0375.
    assert!(close(poisson.work_restitution, 0.035, 1e-15));
    assert!(close(poisson.work_friction, -0.0375, 1e-15));
    assert!(close(poisson.energy_change, -0.1725, 1e-15));
    let names: Vec<&str> = kinds(&poisson).iter().map(|k| k.0).collect();
    assert_eq!(
        names,
        [
            "slides",
            "slip_halts",
            "slip_reverses",
            "slides",
            "max_compression",
            "slides"
        ]
    );
    assert!(close(poisson.phases[1].from_pn, 0.2, 1e-15));
    assert_eq!(
        poisson.phases[2].kind,
        PhaseKind::SlipReverses {
            direction: Vector2::new(-1.0, 0.0)
        }
    );
    assert_eq!(poisson.regime(), Regime::Reverses);
    assert_eq!(poisson.cost, Cost::default(), "closed form costs no steps");

    let newton = integrate(&input(u0, 0.5, 0.5, RestitutionLaw::Newton)).unwrap();
    assert!(close(newton.impulse.x, 0.4 + 2.0 / 7.0, 1e-15));
    assert!(close(newton.velocity.x, 0.5, 1e-15));
    let stronge = integrate(&input(u0, 0.5, 0.5, RestitutionLaw::Stronge)).unwrap();
    assert!(close(
        stronge.impulse.x,
        0.4 + (0.0425f64 / 0.875).sqrt(),
        1e-15
    ));
    assert!(close(
        stronge.work_restitution,
        -0.25 * stronge.work_compression,
        1e-14
    ));
}

/// μ = 0.8 ≥ τ = 0.6: slip halts and sticks. u0 = (-1, 0.7): du/dP_n =
/// K(1, -0.8) = (3.7, -3.5), halt at 0.2 with u_n = -0.26; sticking, u_n
/// rises by the Schur complement S = 2.5 - 1.5²/2.5 = 1.6 per unit P_n:
/// P_c = 0.2 + 0.26/1.6 = 0.3625. Poisson e = 0.5: P_n = 0.54375,
/// P_t = -0.16 + 0.6·0.34375 = 0.04625, u = (0.29, 0). Newton ends at u_n = 0.5,
/// stuck: exactly the one-shot sticking impulse K⁻¹(1.5, -0.7) = (0.675, 0.125).
#[test]
fn rod_slip_halts_and_sticks_closed_form() {
    let u0 = Vector3::new(-1.0, 0.7, 0.0);
    let poisson = integrate(&input(u0, 0.8, 0.5, RestitutionLaw::Poisson)).unwrap();
    assert!((poisson.impulse - Vector3::new(0.54375, 0.04625, 0.0)).norm() < 1e-15);
    assert!((poisson.velocity - Vector3::new(0.29, 0.0, 0.0)).norm() < 1e-15);
    assert_eq!(poisson.regime(), Regime::HaltsAndSticks);
    let newton = integrate(&input(u0, 0.8, 0.5, RestitutionLaw::Newton)).unwrap();
    assert!((newton.impulse - Vector3::new(0.675, 0.125, 0.0)).norm() < 1e-15);
}

/// The integrator, forced onto these planar impacts, reproduces the closed forms.
#[test]
fn integrator_reproduces_the_planar_closed_forms() {
    for (u0, mu) in [
        (Vector3::new(-1.0, 0.55, 0.0), 0.5),
        (Vector3::new(-1.0, 0.7, 0.0), 0.8),
        (Vector3::new(-1.0, 3.0, 0.0), 0.3),
    ] {
        for law in RestitutionLaw::ALL {
            let exact = integrate(&input(u0, mu, 0.7, law)).unwrap();
            let mut forced = input(u0, mu, 0.7, law);
            forced.tolerance.always_integrate = true;
            let forced = integrate(&forced).unwrap();
            let diff = (forced.impulse - exact.impulse).norm() / exact.impulse.norm();
            assert!(diff < 1e-9, "{law:?} {u0}: {diff:e}");
            assert_eq!(
                forced.regime(),
                Regime::Rotating,
                "forced counts as integrated"
            );
            assert!(forced.cost.accepted_steps > 0);
            assert!(
                forced.energy_residual() < 1e-9,
                "{}",
                forced.energy_residual()
            );
        }
    }
}

#[test]
fn zero_restitution_ends_at_maximum_compression() {
    for law in RestitutionLaw::ALL {
        let o = integrate(&input(Vector3::new(-1.0, 0.55, 0.0), 0.5, 0.0, law)).unwrap();
        assert!(close(o.impulse.x, 0.4, 1e-15), "{law:?}: {}", o.impulse.x);
        assert!(o.velocity.x.abs() < 1e-15);
    }
}

#[test]
fn separating_contact_gets_no_impulse() {
    let o = integrate(&input(
        Vector3::new(0.5, 1.0, 0.0),
        0.5,
        0.5,
        RestitutionLaw::Poisson,
    ))
    .unwrap();
    assert!(!o.closing);
    assert_eq!(o.impulse, Vector3::zeros());
    assert_eq!(o.regime(), Regime::Separating);
}

#[test]
fn bad_input_is_an_error_not_nan() {
    let base = input(
        Vector3::new(-1.0, 0.5, 0.2),
        0.5,
        0.5,
        RestitutionLaw::Stronge,
    );
    let mut nan = base.clone();
    nan.u0.y = f64::NAN;
    assert_eq!(integrate(&nan), Err(ExactError::NonFinite { what: "u0" }));
    let mut indefinite = base.clone();
    indefinite.k[(1, 1)] = -1.0;
    assert!(matches!(
        integrate(&indefinite),
        Err(ExactError::NotPositiveDefinite { .. })
    ));
    let mut asymmetric = base.clone();
    asymmetric.k[(0, 1)] = 0.0;
    assert!(matches!(
        integrate(&asymmetric),
        Err(ExactError::NotPositiveDefinite { .. })
    ));
    let mut superelastic = base.clone();
    superelastic.restitution = 1.5;
    assert!(matches!(
        integrate(&superelastic),
        Err(ExactError::OutOfRange { what: "e", .. })
    ));
}

/// Regression: a turning slip that settles just before halting. The closed
/// form along the settled direction must halt where the slip along it
/// reaches zero; it once slid on through zero, friction pushing the slip,
/// and Poisson's law "gained" 0.92 of the collision energy.
#[test]
fn settled_slip_halts_instead_of_sliding_through_zero() {
    let k = Matrix3::new(
        1.7388473034424412,
        0.46624820818838675,
        0.31564866177941586,
        0.46624820818838675,
        5.0401475104662286,
        0.21562849646371895,
        0.31564866177941586,
        0.21562849646371895,
        4.5829779216123985,
    );
    let u0 = Vector3::new(-1.599163920814278, -1.2476511142127649, -0.5735371569467951);
    let mut input = ImpactInput {
        k,
        u0,
        static_friction: 0.5913564399965539,
        dynamic_friction: 0.5913564399965539,
        restitution: 0.8333086997745995,
        law: RestitutionLaw::Poisson,
        tolerance: Tolerance::default(),
    };
    let settled = integrate(&input).unwrap();
    input.tolerance.always_integrate = true;
    let forced = integrate(&input).unwrap();
    assert!(settled.work_friction <= 0.0 && settled.energy_change < 0.0);
    assert!(settled
        .phases
        .iter()
        .any(|p| p.kind == PhaseKind::SlipHalts));
    assert!(
        settled.velocity.yz().norm() < 1e-9,
        "ends stuck: {}",
        settled.velocity
    );
    let diff = (settled.impulse - forced.impulse).norm() / forced.impulse.norm();
    assert!(diff < 1e-9, "{diff:e}");
}

/// Stronge's end with a tiny e: W_r = -e² W_c is accumulated from maximum
/// compression on, not as the difference of two nearly equal totals.
#[test]
fn stronge_with_tiny_restitution_stays_exact() {
    let e = 7.3e-6;
    let o = integrate(&input(
        Vector3::new(-1e-3, 0.0, 0.0),
        0.0,
        e,
        RestitutionLaw::Stronge,
    ))
    .unwrap();
    let closed = (1.0 + e) * 1e-3 / 2.5;
    assert!(
        (o.impulse.x - closed).abs() <= 1e-15 * closed,
        "{:e}",
        o.impulse.x / closed - 1.0
    );
}
