//! The integration error of `physics::exact`, measured (the bound stated in
//! the module docs): turning slip at the default tolerance against a run at
//! rtol = 1e-13, the energy residual `|W_c + W_r + W_t − ΔE|`, and planar
//! impacts forced through the integrator against their closed forms. Run
//! with `--nocapture` for the figures.

use crate::exact_support;

use contact_lab::exercise::rng::SplitMix64;
use contact_lab::physics::exact::{exact_impact, integrate, ImpactInput, Regime, RestitutionLaw};
use exact_support::{collision_energy, contact, median, Family};

struct Errors {
    impulse: Vec<f64>,
    residual: Vec<f64>,
}

fn measure(
    family: Family,
    n: usize,
    seed: u64,
    compare: impl Fn(&ImpactInput<f64>) -> ImpactInput<f64>,
) -> Errors {
    let mut rng = SplitMix64::new(seed);
    let mut out = Errors {
        impulse: Vec::new(),
        residual: Vec::new(),
    };
    for _ in 0..n {
        let problem = contact(&mut rng, family);
        for law in RestitutionLaw::ALL {
            let x = exact_impact(&problem, law).unwrap();
            let reference = integrate(&compare(&x.input)).unwrap();
            let o = &x.outcome;
            out.impulse
                .push((o.impulse - reference.impulse).norm() / reference.impulse.norm());
            let scale = collision_energy(&x.input.k, &x.input.u0);
            out.residual.push(o.energy_residual() / scale);
        }
    }
    out
}

fn report(name: &str, e: &mut Errors) -> (f64, f64) {
    let max_p = e.impulse.iter().cloned().fold(0.0, f64::max);
    let max_r = e.residual.iter().cloned().fold(0.0, f64::max);
    println!(
        "{name:52} |ΔP|/|P| median {:.1e} max {max_p:.1e}; residual/E_c median {:.1e} max {max_r:.1e}",
        median(&mut e.impulse),
        median(&mut e.residual)
    );
    (max_p, max_r)
}

#[test]
fn turning_slip_against_a_tighter_run() {
    let tight = |input: &ImpactInput<f64>| {
        let mut t = input.clone();
        t.tolerance.rtol = 1e-13;
        t
    };
    let mut e = measure(Family::General, 400, 7, tight);
    let (p, r) = report("3D contacts, rtol 1e-10 vs 1e-13", &mut e);
    assert!(p < 1e-8, "{p:e}");
    assert!(r < 1e-8, "{r:e}");
}

#[test]
fn settling_on_an_invariant_direction_against_integrating_on() {
    let on = |input: &ImpactInput<f64>| {
        let mut t = input.clone();
        t.tolerance.always_integrate = true;
        t
    };
    let mut e = measure(Family::General, 400, 8, on);
    let (p, _) = report("3D contacts, settled closed form vs integrated", &mut e);
    assert!(p < 1e-8, "{p:e}");
}

#[test]
fn planar_closed_forms_through_the_integrator() {
    let forced = |input: &ImpactInput<f64>| {
        let mut t = input.clone();
        t.tolerance.always_integrate = true;
        t
    };
    // Here the reference is the integrator and the measured run the closed form.
    let mut rng = SplitMix64::new(9);
    let mut e = Errors {
        impulse: Vec::new(),
        residual: Vec::new(),
    };
    for _ in 0..400 {
        let problem = contact(&mut rng, Family::Planar);
        for law in RestitutionLaw::ALL {
            let x = exact_impact(&problem, law).unwrap();
            assert_ne!(x.outcome.regime(), Regime::Rotating);
            let integrated = integrate(&forced(&x.input)).unwrap();
            e.impulse
                .push((integrated.impulse - x.outcome.impulse).norm() / x.outcome.impulse.norm());
            let scale = collision_energy(&x.input.k, &x.input.u0);
            e.residual.push(integrated.energy_residual() / scale);
        }
    }
    let (p, r) = report("planar contacts, integrated vs closed form", &mut e);
    assert!(p < 1e-8, "{p:e}");
    assert!(r < 1e-8, "{r:e}");
}
