//! `contact-lab check` (the default run over every embedded lesson) lists
//! the XPBD paper's dynamic-friction erratum beside the lecture's: both
//! formulas and the deceleration of a sliding box under each, the figures
//! the measurement gives (a label is the value it names).

use assert_cmd::Command;
use contact_lab::errata::xpbd::{self, sliding_deceleration};
use contact_lab::physics::step::xpbd::DynamicFriction;

fn check(args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .arg("check")
        .args(args)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "check {args:?}");
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn check_json_gives_the_xpbd_erratum_with_the_measured_decelerations() {
    let json: serde_json::Value = serde_json::from_str(&check(&["--format", "json"])).unwrap();
    let paper = &json["papers"][0];
    assert_eq!(paper["printed"], xpbd::PRINTED);
    assert_eq!(paper["corrected"], xpbd::CORRECTED);
    let rows = paper["measured"].as_array().expect("measured rows");
    assert_eq!(rows.len(), xpbd::MASSES.len());
    let mu_g = xpbd::MU_D * xpbd::G;
    for row in rows {
        let mass = row["mass"].as_f64().unwrap();
        let printed = row["printed_deceleration"].as_f64().unwrap();
        let corrected = row["corrected_deceleration"].as_f64().unwrap();
        assert_eq!(
            Some(printed),
            sliding_deceleration(mass, DynamicFriction::Printed)
        );
        assert_eq!(
            Some(corrected),
            sliding_deceleration(mass, DynamicFriction::Corrected)
        );
        // The corrected deceleration does not depend on the mass (0.868
        // μ_d g under one position iteration a substep).
        assert!(
            (corrected / mu_g - 0.868).abs() < 0.005,
            "{mass} kg: {corrected}"
        );
    }
    // The printed one grows with the mass: about m/4 kg of the corrected
    // (a corner of a 1 m cube has w = 4/m), equal near 4 kg.
    let ratios: Vec<f64> = rows
        .iter()
        .map(|r| {
            r["printed_deceleration"].as_f64().unwrap()
                / r["corrected_deceleration"].as_f64().unwrap()
        })
        .collect();
    assert!(ratios.windows(2).all(|w| w[1] > 1.5 * w[0]), "{ratios:?}");
    assert!((ratios[2] - 1.0).abs() < 0.01, "4 kg: {ratios:?}");
}

#[test]
fn check_text_names_both_formulas_and_the_measured_figures() {
    let text = check(&["--width", "400"]);
    assert!(text.contains("Müller et al. 2020"), "{text}");
    assert!(text.contains(xpbd::PRINTED), "{text}");
    assert!(text.contains(xpbd::CORRECTED), "{text}");
    let corrected = sliding_deceleration(1.0, DynamicFriction::Corrected).unwrap();
    let shown = contact_lab::format::Fmt::default().num(corrected);
    assert!(
        text.contains("1 kg: printed") && text.contains(&format!("corrected {shown}")),
        "{text}"
    );
}

#[test]
fn check_of_named_lessons_checks_only_those() {
    let json: serde_json::Value =
        serde_json::from_str(&check(&["lecture-1", "--format", "json"])).unwrap();
    assert!(json.get("papers").is_none());
}
