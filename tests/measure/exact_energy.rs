//! Energy under each restitution law on Kane's lesson (run with
//! `--nocapture` for the report). Where the laws gain energy over random
//! contacts is counted in `exact_study.rs`.

use contact_lab::knobs::Choice;
use std::collections::BTreeMap;

use contact_lab::lesson::Lesson;
use contact_lab::physics::exact::{exact_impact, Regime, RestitutionLaw};

fn names(phases: &[contact_lab::physics::exact::Phase<f64>]) -> String {
    phases
        .iter()
        .map(|p| format!("{}@{:.4}", p.kind.name(), p.to_pn))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Kane's example (lesson `kane-energy-gain`): the one-shot's Newton
/// restitution with sticking friction gains about 21 %.
#[test]
fn kane_lesson_by_law() {
    let problem = Lesson::load("kane-energy-gain").unwrap().problem::<f64>(0);
    println!("kane-energy-gain: ΔE/E_before");
    let mut gain = BTreeMap::new();
    for law in RestitutionLaw::ALL {
        let x = exact_impact(&problem, law).unwrap();
        let one_shot = (x.energy_after_one_shot - x.energy_before) / x.energy_before;
        let exact = x.energy_change() / x.energy_before;
        println!(
            "  {:8} exact {:+.4} ({:?}: {})  one-shot {:+.4}  |ΔP|/|P| = {:.3e}",
            Some(law).name(),
            exact,
            x.outcome.regime(),
            names(&x.outcome.phases),
            one_shot,
            x.impulse_difference_relative()
        );
        gain.insert(Some(law).name(), (exact, one_shot, x.outcome.regime()));
    }
    // The rod's end slides, halts and sticks under every law. Newton then ends
    // at u = (−e u_n0, 0), the one-shot's target: integrating changes nothing
    // and the +21 % stays. Poisson and Stronge end the restitution earlier
    // (the sticking rod's normal velocity rises slowly) and dissipate.
    let (newton, one_shot, _) = gain["newton"];
    assert!(
        one_shot > 0.2 && one_shot < 0.22,
        "the lesson's +21 %: {one_shot}"
    );
    assert!(
        (newton - one_shot).abs() < 1e-12,
        "integrated Newton = one-shot: {newton}"
    );
    for law in ["newton", "poisson", "stronge"] {
        assert_eq!(gain[law].2, Regime::HaltsAndSticks, "{law}");
    }
    assert!(
        gain["poisson"].0 < -0.3,
        "Poisson dissipates: {}",
        gain["poisson"].0
    );
    assert!(
        gain["stronge"].0 < -0.2,
        "Stronge dissipates: {}",
        gain["stronge"].0
    );
}
