//! The impact integration (`physics::exact`) against closed forms: no
//! friction, sticking from the start, a ball and a rod on a rough floor;
//! energy consistency; Kane's lesson; errors instead of NaN.

use crate::common;
use crate::exact_support;

use contact_lab::exercise::rng::SplitMix64;
use contact_lab::lesson::Lesson;
use contact_lab::physics::exact::{
    exact_impact, integrate, ExactError, ImpactInput, Regime, RestitutionLaw, Tolerance,
};
use contact_lab::physics::{solve, ContactInput, ContactParams, FrictionModel, Problem, RigidBody};
use exact_support::{about_z, collision_energy, contact, spd, uniform, Family};
use nalgebra::{Matrix3, Vector3};
use proptest::prelude::*;

fn relative(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    (a - b).norm() / b.norm().max(1e-300)
}

fn kernel(
    k: Matrix3<f64>,
    u0: Vector3<f64>,
    mu: (f64, f64),
    e: f64,
    law: RestitutionLaw,
) -> ImpactInput<f64> {
    ImpactInput {
        k,
        u0,
        static_friction: mu.0,
        dynamic_friction: mu.1,
        restitution: e,
        law,
        tolerance: Tolerance::default(),
    }
}

/// Without friction every law gives the closed form `P_n = −(1+e) u_n0 / K_nn`
/// (K_nn = the stages' Δq̇_t): every closing contact of every lesson.
#[test]
fn frictionless_lessons_all_laws_equal_the_closed_form() {
    let mut checked = 0;
    for lesson in common::all_lessons() {
        for k in 0..lesson.contacts.len() {
            let mut problem = lesson.problem::<f64>(k);
            problem.contact.static_friction = 0.0;
            problem.contact.dynamic_friction = 0.0;
            let one_shot = solve(&problem);
            for law in RestitutionLaw::ALL {
                let exact = exact_impact(&problem, law).unwrap();
                let (u0, kk) = (exact.input.u0, exact.input.k);
                if u0.x >= 0.0 {
                    assert_eq!(exact.outcome.regime(), Regime::Separating);
                    continue;
                }
                let closed = -(1.0 + problem.contact.restitution) * u0.x / kk[(0, 0)];
                let p = exact.outcome.impulse;
                let id = format!("{} #{k} {law:?}", lesson.id);
                assert!(
                    (p.x - closed).abs() <= 1e-14 * closed,
                    "{id}: {} vs {closed}",
                    p.x
                );
                assert_eq!((p.y, p.z), (0.0, 0.0), "{id}");
                assert_eq!(exact.outcome.regime(), Regime::Frictionless, "{id}");
                // The one-shot applies the same impulse where it uses the same
                // restitution (no velocity limit, no acceleration compensation).
                let d = &one_shot.desired;
                if !d.restitution_limited && d.velocity_from_acceleration == 0.0 {
                    let g = one_shot.final_impulse_world().unwrap();
                    assert!(relative(&exact.impulse_world, &g) < 1e-12, "{id}");
                }
                checked += 1;
            }
        }
    }
    assert!(checked >= 60, "{checked} checks");
}

/// Removes the tangential contact velocity through body 1's velocity.
fn at_rest(mut problem: Problem<f64>) -> Problem<f64> {
    let n = problem.contact.normal;
    let u = exact_support::contact_velocity(&problem);
    problem.bodies[0].as_mut().unwrap().velocity -= u - n * u.dot(&n);
    problem
}

/// Sticking from the start: every law gives the one-shot sticking impulse
/// K⁻¹(−(1+e) u_n0, 0, 0) — real lessons set down without sliding.
#[test]
fn sticking_from_the_start_equals_the_one_shot_on_lessons() {
    let cases = [
        ("friction-cube", 0),
        ("friction-cube", 1),
        ("kane-energy-gain", 0),
        ("spinning-ball", 0),
        ("two-boxes", 0),
    ];
    let mut sticking = 0;
    for (id, k) in cases {
        let problem = at_rest(Lesson::load(id).unwrap().problem::<f64>(k));
        let one_shot = solve(&problem);
        for law in RestitutionLaw::ALL {
            let exact = exact_impact(&problem, law).unwrap();
            if exact.outcome.regime() != Regime::SticksThroughout {
                continue;
            }
            sticking += 1;
            let g = one_shot.final_impulse_world().unwrap();
            let rel = relative(&exact.impulse_world, &g);
            assert!(rel < 1e-12, "{id} #{k} {law:?}: {rel:e}");
            assert!(
                exact.outcome.velocity.y.abs() < 1e-12 && exact.outcome.velocity.z.abs() < 1e-12
            );
        }
    }
    assert!(sticking >= 9, "only {sticking} sticking cases");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn frictionless_kernel_is_the_closed_form(seed in any::<u64>(), un in -10.0..-1e-3f64, e in 0.0..=1.0f64) {
        let mut rng = SplitMix64::new(seed);
        let k = spd(&mut rng);
        let u0 = Vector3::new(un, uniform(&mut rng, -5.0, 5.0), uniform(&mut rng, -5.0, 5.0));
        let closed = -(1.0 + e) * un / k[(0, 0)];
        for law in RestitutionLaw::ALL {
            let o = integrate(&kernel(k, u0, (0.0, 0.0), e, law)).unwrap();
            prop_assert!((o.impulse.x - closed).abs() <= 1e-14 * closed, "{law:?}");
            prop_assert_eq!((o.impulse.y, o.impulse.z), (0.0, 0.0));
        }
    }

    #[test]
    fn sticking_kernel_is_the_one_shot(seed in any::<u64>(), un in -10.0..-1e-3f64, e in 0.0..=1.0f64, margin in 1.0..3.0f64) {
        let mut rng = SplitMix64::new(seed);
        let k = spd(&mut rng);
        // μ_s ≥ |τ|: the cone holds the contact from the first impulse on.
        let tau = -k.fixed_view::<2, 2>(1, 1).into_owned().try_inverse().unwrap()
            * nalgebra::Vector2::new(k[(1, 0)], k[(2, 0)]);
        let mu = tau.norm() * margin;
        let u0 = Vector3::new(un, 0.0, 0.0);
        let one_shot = k.cholesky().unwrap().solve(&Vector3::new(-(1.0 + e) * un, 0.0, 0.0));
        for law in RestitutionLaw::ALL {
            let o = integrate(&kernel(k, u0, (mu, 0.8 * mu), e, law)).unwrap();
            prop_assert_eq!(o.regime(), Regime::SticksThroughout);
            // The same algebra by two routes: round-off grows with κ(K), which
            // for a random K reaches 10⁴, so 1e-12 alone failed on one seed (1.05e-12).
            let eig = k.symmetric_eigenvalues();
            let kappa = eig.max() / eig.min();
            let bound = 1e-14 * kappa.max(100.0);
            prop_assert!(relative(&o.impulse, &one_shot) < bound, "{law:?}: {:e} (κ {kappa:e})", relative(&o.impulse, &one_shot));
        }
    }

    /// Stronge's law never gains energy: ΔE = (1 − e²) W_c + W_t ≤ 0.
    #[test]
    fn stronge_never_gains_energy(seed in any::<u64>(), mu_s in 0.0..1.5f64, mu_d in 0.0..1.5f64, e in 0.0..=1.0f64) {
        let mut rng = SplitMix64::new(seed);
        let k = spd(&mut rng);
        let mut u0 = exact_support::vector(&mut rng, 3.0);
        u0.x = -u0.x.abs() - 1e-3;
        let o = integrate(&kernel(k, u0, (mu_s, mu_d), e, RestitutionLaw::Stronge)).unwrap();
        let scale = collision_energy(&k, &u0);
        prop_assert!(o.energy_change <= 1e-9 * scale, "ΔE = {:e} of {scale:e}, {:?}", o.energy_change, o.regime());
        prop_assert!(o.work_friction <= 1e-12 * scale);
        prop_assert!((o.work_restitution + e * e * o.work_compression).abs() <= 1e-8 * scale);
        // The residual is the integration's error where the slip turns: 2.1e-9
        // of the collision energy over tests/measure/exact_accuracy.rs's contacts, but
        // 2.0e-8 on one seed proptest found (μ_s = 0 < μ_d = 1.31, e = 0, a
        // turning slip; in the regressions file), so the bound is 5e-8.
        prop_assert!(o.energy_residual() <= 5e-8 * scale, "residual {:e} of {scale:e}, {:?}, {} evals", o.energy_residual(), o.regime(), o.cost.rhs_evals);
    }
}

/// A solid ball (I = 2/5 m R²) spinning onto a rough floor: K_nt = 0 and
/// K_tt = (1/m)(1 + m R²/I) = 7/(2m) 𝟙, so u_n rises at 1/m whatever friction
/// does (all laws agree, P_n = (1+e) m |u_n0|) and the slip keeps its
/// direction, slowing by 7μ/(2m) per unit P_n. It halts at P_h = 2m|u_t0|/(7μ):
/// if P_h < P_n the ball leaves rolling (u_t' = 0, P_t = −(2m/7) u_t0),
/// otherwise P_t = −μ P_n u_t0/|u_t0| (Brach; Stronge, Impact Mechanics §5).
#[test]
fn ball_on_a_rough_floor() {
    let (m, radius) = (2.0, 0.5);
    let moment = 0.4 * m * radius * radius;
    for (v, w, mu, e) in [
        (
            Vector3::new(1.0, -3.0, 0.5),
            Vector3::new(2.0, 0.0, -4.0),
            0.5,
            0.6,
        ), // halts, rolls
        (
            Vector3::new(4.0, -1.0, -2.0),
            Vector3::new(0.0, 1.0, 3.0),
            0.1,
            0.8,
        ), // slides throughout
    ] {
        let problem = Problem {
            bodies: [
                Some(RigidBody {
                    mass: m,
                    inverse_mass: 1.0 / m,
                    inertia_body: Matrix3::identity() * moment,
                    inverse_inertia_body: Matrix3::identity() / moment,
                    position: Vector3::new(0.0, radius, 0.0),
                    orientation: about_z(0.3),
                    velocity: v,
                    angular_velocity: w,
                    acceleration: Vector3::zeros(),
                }),
                None,
            ],
            contact: ContactInput {
                point: Vector3::zeros(),
                normal: Vector3::y(),
                penetration: 0.0,
                restitution: e,
                static_friction: mu,
                dynamic_friction: mu,
                friction_model: FrictionModel::Millington,
                settings: ContactParams::default(),
            },
            duration: 0.01,
        };
        let r = Vector3::new(0.0, -radius, 0.0);
        let u = v + w.cross(&r);
        let ut = Vector3::new(u.x, 0.0, u.z);
        let p_n = (1.0 + e) * m * -u.y;
        let p_h = 2.0 * m * ut.norm() / (7.0 * mu);
        let (p_t, regime) = if p_h < p_n {
            (-ut * (2.0 * m / 7.0), Regime::HaltsAndSticks)
        } else {
            (-ut / ut.norm() * mu * p_n, Regime::SlidesThroughout)
        };
        let expected = Vector3::new(p_t.x, p_n, p_t.z);
        for law in RestitutionLaw::ALL {
            let exact = exact_impact(&problem, law).unwrap();
            assert_eq!(exact.outcome.regime(), regime, "{law:?}");
            assert!(
                relative(&exact.impulse_world, &expected) < 1e-14,
                "{law:?}: {} vs {expected}",
                exact.impulse_world
            );
            let after = exact.applied.bodies[0].as_ref().unwrap();
            let spin = w + r.cross(&expected) / moment;
            assert!((after.v - (v + expected / m)).norm() < 1e-14);
            assert!((after.w - spin).norm() < 1e-13);
            if regime == Regime::HaltsAndSticks {
                let rolling = after.v + after.w.cross(&r);
                assert!(
                    rolling.x.abs() < 1e-14 && rolling.z.abs() < 1e-14,
                    "rolls: {rolling}"
                );
            }
        }
    }
}

/// The 45° rod of the kernel's unit tests, as a body: m = 1, length 2,
/// I_zz = 1/3, lower end at the origin, r = (−1/√2, −1/√2, 0), falling at
/// (0.55, −1, 0) without spin, μ = 0.5, e = 0.5. In (n = y, t = x):
/// K = [[2.5, −1.5], [−1.5, 2.5]]; the slip (+x) halts at P_n = 0.2 and
/// reverses (|τ| = 0.6 > μ); compression ends at 0.4; Poisson ends at 0.6
/// with P_t = −0.1 + 0.2 = 0.1, so P = (0.1, 0.6, 0), v' = (0.65, −0.4, 0) and
/// ω_z' = (r_x P_y − r_y P_x)/I = −(0.5/√2)·3 = −1.0607; the end leaves at
/// (−0.1, 0.35, 0): sliding back.
#[test]
fn rod_on_a_rough_floor_slips_back() {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0 / 3.0, 0.01, 1.0 / 3.0));
    let problem = Problem {
        bodies: [
            Some(RigidBody {
                mass: 1.0,
                inverse_mass: 1.0,
                inertia_body: inertia,
                inverse_inertia_body: inertia.try_inverse().unwrap(),
                position: Vector3::new(h, h, 0.0),
                orientation: about_z(-std::f64::consts::FRAC_PI_4),
                velocity: Vector3::new(0.55, -1.0, 0.0),
                angular_velocity: Vector3::zeros(),
                acceleration: Vector3::zeros(),
            }),
            None,
        ],
        contact: ContactInput {
            point: Vector3::zeros(),
            normal: Vector3::y(),
            penetration: 0.0,
            restitution: 0.5,
            static_friction: 0.5,
            dynamic_friction: 0.5,
            friction_model: FrictionModel::Millington,
            settings: ContactParams::default(),
        },
        duration: 0.01,
    };
    let exact = exact_impact(&problem, RestitutionLaw::Poisson).unwrap();
    assert_eq!(exact.outcome.regime(), Regime::Reverses);
    assert!(
        (exact.impulse_world - Vector3::new(0.1, 0.6, 0.0)).norm() < 1e-14,
        "{}",
        exact.impulse_world
    );
    let after = exact.applied.bodies[0].as_ref().unwrap();
    assert!((after.v - Vector3::new(0.65, -0.4, 0.0)).norm() < 1e-14);
    assert!((after.w.z + 1.5 * h).abs() < 1e-14, "{}", after.w);
    let r = Vector3::new(-h, -h, 0.0);
    assert!((after.v + after.w.cross(&r) - Vector3::new(-0.1, 0.35, 0.0)).norm() < 1e-14);
    // The energy bookkeeping: bodies' kinetic energy change = P·u0 + ½PᵀKP = −0.1725.
    assert!(
        (exact.energy_change() + 0.1725).abs() < 1e-14,
        "{}",
        exact.energy_change()
    );
}

/// The bodies' energy change equals the kernel's ΔE = P·u0 + ½PᵀKP.
#[test]
fn bodies_energy_change_matches_the_kernel() {
    let mut rng = SplitMix64::new(15);
    for i in 0..300 {
        let family = [
            Family::General,
            Family::Planar,
            Family::AtRest { planar: false },
        ][i % 3];
        let problem = contact(&mut rng, family);
        for law in RestitutionLaw::ALL {
            let exact = exact_impact(&problem, law).unwrap();
            let scale = collision_energy(&exact.input.k, &exact.input.u0);
            let diff = exact.energy_change() - exact.outcome.energy_change;
            assert!(
                diff.abs() < 1e-10 * (scale + exact.energy_before),
                "{i} {law:?}: {diff:e}"
            );
        }
    }
}

/// Halting and sticking under Newton's law ends at u = (−e u_n0, 0): exactly
/// the one-shot sticking impulse. The lecture's cube (friction-cube #0) slides
/// at 2.165, halts and sticks.
#[test]
fn newton_that_halts_and_sticks_is_the_one_shot() {
    let problem = Lesson::load("friction-cube").unwrap().problem::<f64>(0);
    let exact = exact_impact(&problem, RestitutionLaw::Newton).unwrap();
    assert_eq!(exact.outcome.regime(), Regime::HaltsAndSticks);
    assert!(
        exact.impulse_difference_relative() < 1e-12,
        "{:e}",
        exact.impulse_difference_relative()
    );
    for law in [RestitutionLaw::Poisson, RestitutionLaw::Stronge] {
        let other = exact_impact(&problem, law).unwrap();
        assert!(
            other.impulse_difference_relative() > 1e-3,
            "{law:?} differs from the one-shot"
        );
    }
}

#[test]
fn budget_exceeded_is_an_error_not_nan() {
    let k = Matrix3::new(2.5, -1.5, 0.3, -1.5, 2.5, 0.2, 0.3, 0.2, 4.0);
    let mut input = kernel(
        k,
        Vector3::new(-1.0, 0.5, 0.4),
        (0.3, 0.3),
        0.5,
        RestitutionLaw::Stronge,
    );
    assert!(integrate(&input).is_ok());
    input.tolerance.max_steps = 5;
    let err = integrate(&input).unwrap_err();
    assert!(
        matches!(err, ExactError::BudgetExceeded { budget: 5, .. }),
        "{err:?}"
    );
    assert!(err.to_string().contains("budget of 5 steps"), "{err}");
    let mut overflow = input.clone();
    overflow.tolerance.max_steps = 10_000;
    overflow.u0 *= 1e300;
    overflow.k *= 1e300;
    assert!(
        integrate(&overflow).is_err(),
        "1e300 overflows: an error, not inf or NaN"
    );
}

/// The kernel is generic: f32 follows f64 to its default tolerance.
#[test]
fn f32_follows_f64() {
    let k = Matrix3::new(2.5, -1.5, 0.3, -1.5, 2.5, 0.2, 0.3, 0.2, 4.0);
    let u0 = Vector3::new(-1.0, 0.5, 0.4);
    for law in RestitutionLaw::ALL {
        let o64 = integrate(&kernel(k, u0, (0.9, 0.9), 0.5, law)).unwrap();
        let o32 = integrate(&ImpactInput {
            k: k.cast::<f32>(),
            u0: u0.cast::<f32>(),
            static_friction: 0.9,
            dynamic_friction: 0.9,
            restitution: 0.5,
            law,
            tolerance: Tolerance::default(),
        })
        .unwrap();
        assert_eq!(o32.regime(), o64.regime());
        let rel = relative(&o32.impulse.cast::<f64>(), &o64.impulse);
        assert!(rel < 1e-3, "{law:?}: {rel:e}");
    }
    // And from a lesson, through the stages in f32.
    let lesson = Lesson::load("friction-cube").unwrap();
    let x64 = exact_impact(&lesson.problem::<f64>(0), RestitutionLaw::Stronge).unwrap();
    let x32 = exact_impact(&lesson.problem_centred::<f32>(0), RestitutionLaw::Stronge).unwrap();
    let rel = relative(&x32.impulse_world.cast::<f64>(), &x64.impulse_world);
    assert!(rel < 1e-5, "{rel:e}");
}
