//! The `exact_impact` stage as `solve` shows it: skipped unless asked, the
//! frictionless and sticking identities through the stage's values, energy
//! (Stronge never gains, Newton gains on Kane's rod, with the note), the
//! rod whose slip halts and reverses, `--exact` on the command line, and
//! snapshots of the stage under each law for the lessons that show it.

use crate::common;
use contact_lab::knobs::Choice;

use assert_cmd::Command;
use contact_lab::format::Fmt;
use contact_lab::lesson::{Lesson, Overrides};
use contact_lab::physics::exact::RestitutionLaw;
use contact_lab::render;
use contact_lab::render::fill::Fill;
use contact_lab::trace::{Trace, Value};

fn with_law(mut lesson: Lesson, law: RestitutionLaw) -> Lesson {
    lesson.apply(&Overrides::from_pairs(&[("exact", Some(law).name())]).unwrap());
    lesson
}

fn trace(lesson: &Lesson, k: usize) -> Trace {
    contact_lab::worked_solution(lesson, k)
}

fn phases(t: &Trace) -> Vec<String> {
    match t.value("exact_impact", "phases") {
        Some(Value::List(items)) => items.clone(),
        other => panic!("phases: {other:?}"),
    }
}

/// The phase names, without their impulses.
fn phase_names(t: &Trace) -> Vec<String> {
    phases(t)
        .iter()
        .map(|p| p.split(' ').next().unwrap().to_string())
        .collect()
}

/// The stage's notes, numbers filled in.
fn notes(t: &Trace) -> String {
    let step = t.stage("exact_impact").unwrap();
    let fmt = Fmt::default();
    step.notes
        .iter()
        .map(|n| fmt.fill(n, step, false))
        .collect::<Vec<_>>()
        .join("\n")
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    let d: f64 = (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
    let n: f64 = (0..3).map(|i| b[i].powi(2)).sum::<f64>().sqrt();
    d <= tol * n.max(1e-300)
}

#[test]
fn skipped_unless_asked_and_for_a_contact_that_is_not_closing() {
    let lesson = Lesson::load("lecture-2").unwrap();
    let t = trace(&lesson, 0);
    let step = t.stage("exact_impact").unwrap();
    assert!(step.skipped.as_deref().unwrap().starts_with("not asked"));
    assert!(step.values.is_empty());
    // The stage sits after orientation_update and before checks.
    let ids: Vec<_> = t.stages.iter().map(|s| s.id.json_name()).collect();
    let at = ids.iter().position(|&i| i == "exact_impact").unwrap();
    assert_eq!(ids[at - 1], "orientation_update");
    assert_eq!(ids[at + 1], "checks");
    // Newton's cradle has contacts that separate: asked, still skipped, with the reason.
    let cradle = with_law(
        Lesson::load("newtons-cradle").unwrap(),
        RestitutionLaw::Stronge,
    );
    let skipped: Vec<_> = (0..cradle.contacts.len())
        .filter_map(|k| {
            trace(&cradle, k)
                .stage("exact_impact")
                .unwrap()
                .skipped
                .clone()
        })
        .collect();
    assert!(!skipped.is_empty());
    assert!(
        skipped.iter().all(|s| s.contains("not closing")),
        "{skipped:?}"
    );
}

/// Without friction all three laws give the stages' closed form: the one-shot impulse.
#[test]
fn frictionless_every_law_equals_the_stages_impulse() {
    for law in RestitutionLaw::ALL {
        let lesson = with_law(Lesson::load("lecture-2").unwrap(), law);
        let t = trace(&lesson, 0);
        let exact = common::vector(&t, "exact_impact", "impulse_world");
        let one_shot = common::vector(&t, "impulse", "impulse_world");
        assert!(
            close(exact, one_shot, 1e-14),
            "{law:?}: {exact:?} vs {one_shot:?}"
        );
        assert_eq!(
            common::vector(&t, "exact_impact", "impulse_one_shot_world"),
            one_shot
        );
        assert!(common::scalar(&t, "exact_impact", "impulse_difference_relative") < 1e-14);
        assert_eq!(
            phase_names(&t),
            ["frictionless", "max_compression", "frictionless"]
        );
        assert_eq!(common::text(&t, "exact_impact", "regime"), "frictionless");
        // The velocities after match apply_impulse's.
        let v = common::vector(&t, "exact_impact", "v1");
        assert!(close(v, common::vector(&t, "apply_impulse", "v1"), 1e-14));
    }
}

/// A contact at rest tangentially that the cone holds sticks throughout;
/// under Poisson's law its impulse is the one-shot sticking impulse.
#[test]
fn sticking_from_the_start_with_poisson_equals_the_one_shot() {
    let mut lesson = Lesson::load("rod-reverses").unwrap();
    lesson.bodies[0].velocity = nalgebra::Vector3::new(0.0, -2.0, 0.0);
    lesson.contacts[0].static_friction = 1.0;
    lesson.contacts[0].dynamic_friction = 1.0;
    let lesson = with_law(lesson, RestitutionLaw::Poisson);
    let t = trace(&lesson, 0);
    assert_eq!(common::text(&t, "friction_clamp", "regime"), "static");
    assert_eq!(
        common::text(&t, "exact_impact", "regime"),
        "sticks throughout"
    );
    assert_eq!(phase_names(&t), ["sticks", "max_compression", "sticks"]);
    let exact = common::vector(&t, "exact_impact", "impulse_world");
    let one_shot = common::vector(&t, "friction_clamp", "impulse_world");
    assert!(close(exact, one_shot, 1e-13), "{exact:?} vs {one_shot:?}");
    let e = common::scalar(&t, "exact_impact", "energy_difference");
    assert!(e.abs() < 1e-13, "{e}");
}

/// Stronge's law never gains energy, on any closing contact of any lesson;
/// its stage never carries the gain note for the integrated impulse.
#[test]
fn stronge_never_gains_energy_on_any_lesson() {
    let mut checked = 0;
    for lesson in common::all_lessons() {
        let lesson = with_law(lesson, RestitutionLaw::Stronge);
        for k in 0..lesson.contacts.len() {
            let t = trace(&lesson, k);
            if t.stage("exact_impact").unwrap().skipped.is_some() {
                continue;
            }
            let before = common::scalar(&t, "exact_impact", "energy_before");
            let after = common::scalar(&t, "exact_impact", "energy_after");
            assert!(
                after <= before * (1.0 + 1e-12),
                "{} #{k}: {before} → {after}",
                lesson.id
            );
            assert!(!notes(&t).contains("ENERGY GAIN: the integrated"));
            checked += 1;
        }
    }
    assert!(checked >= 20, "{checked} contacts checked");
}

/// Kane's rod: Newton's law gains 21 % (and the stage says why), Poisson
/// and Stronge lose energy.
#[test]
fn kane_rod_under_the_three_laws() {
    let gain = |law| {
        let t = trace(&with_law(Lesson::load("kane-energy-gain").unwrap(), law), 0);
        let before = common::scalar(&t, "exact_impact", "energy_before");
        let after = common::scalar(&t, "exact_impact", "energy_after");
        (after / before - 1.0, notes(&t))
    };
    let (newton, note) = gain(RestitutionLaw::Newton);
    assert!((newton - 0.21176).abs() < 1e-4, "{newton}");
    assert!(
        note.contains("ENERGY GAIN: the integrated impulse raises the kinetic energy by 21.176 %")
    );
    assert!(note.contains("Newton's law with friction is not energetically consistent"));
    let (poisson, note) = gain(RestitutionLaw::Poisson);
    assert!((poisson + 0.3687).abs() < 1e-3, "{poisson}");
    assert!(!note.contains("ENERGY GAIN: the integrated"));
    let (stronge, note) = gain(RestitutionLaw::Stronge);
    assert!((stronge + 0.2877).abs() < 1e-3, "{stronge}");
    assert!(note.contains("Stronge's law never gains energy"));
    // The one-shot gains, whatever the law beside it.
    assert!(note.contains("ENERGY GAIN: the one-shot impulse"));
}

/// The rod lesson: slides, halts, reverses during compression, slides on;
/// the one-shot differs by more than a third.
#[test]
fn rod_lesson_slip_halts_and_reverses() {
    let lesson = Lesson::load("rod-reverses").unwrap();
    let t = trace(&lesson, 0);
    assert_eq!(common::text(&t, "exact_impact", "law"), "stronge");
    assert_eq!(common::text(&t, "exact_impact", "regime"), "reverses");
    assert_eq!(
        phase_names(&t),
        [
            "slides",
            "slip_halts",
            "slip_reverses",
            "slides",
            "max_compression",
            "slides"
        ]
    );
    let halt: f64 = phases(&t)[1].rsplit(' ').next().unwrap().parse().unwrap();
    let pc = common::scalar(&t, "exact_impact", "compression_normal_impulse");
    assert!(
        halt > 0.0 && halt < pc,
        "halts at {halt}, compression ends at {pc}"
    );
    let relative = common::scalar(&t, "exact_impact", "impulse_difference_relative");
    assert!((0.35..0.4).contains(&relative), "{relative}");
    assert!(common::scalar(&t, "exact_impact", "energy_difference") > 0.0);
    // The works add up to the energy change.
    let w: f64 = ["work_compression", "work_restitution", "work_friction"]
        .iter()
        .map(|n| common::scalar(&t, "exact_impact", n))
        .sum();
    let de = common::scalar(&t, "exact_impact", "energy_change");
    assert!((w - de).abs() < 1e-12, "{w} vs {de}");
}

/// `--exact` overrides the lesson's law; JSON carries the contract's values.
#[test]
fn exact_on_the_command_line() {
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args([
            "solve",
            "rod-reverses",
            "--exact",
            "newton",
            "--format",
            "json",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let stage = json["stages"]
        .as_array()
        .unwrap()
        .iter()
        .find(|s| s["id"] == "exact_impact")
        .unwrap();
    assert!(stage["skipped"].is_null());
    let values = &stage["values"];
    assert_eq!(values["law"], "newton");
    for key in [
        "impulse_world",
        "impulse_one_shot_world",
        "v1",
        "w1",
        "energy_before",
        "energy_after",
        "energy_after_one_shot",
    ] {
        assert!(!values[key].is_null(), "{key}");
    }
    assert_eq!(values["phases"].as_array().unwrap().len(), 6);
    assert!(values["phases"][1]
        .as_str()
        .unwrap()
        .starts_with("slip_halts at P_n = "));
    let bad = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args(["solve", "rod-reverses", "--exact", "hooke"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
}

/// The `exact_impact` stage as `solve` prints it.
fn stage_text(t: &Trace) -> String {
    let step = t.stage("exact_impact").unwrap();
    let fmt = Fmt::default();
    let mut out = format!("{} [{}]\n", step.title, step.id.json_name());
    if let Some(why) = &step.skipped {
        out.push_str(&format!("skipped: {why}\n"));
    }
    for f in &step.formulas {
        for line in render::contact::text::formula_lines(f, step, &fmt) {
            out.push_str(&format!("   {line}\n"));
        }
    }
    for note in &step.notes {
        out.push_str(&format!("   · {}\n", fmt.fill(note, step, false)));
    }
    out
}

/// The stage's text under each law, for the lessons that show it.
#[test]
fn exact_stage_snapshots() {
    let cases: &[(&str, usize)] = &[
        ("rod-reverses", 0),
        ("kane-energy-gain", 0),
        ("spinning-ball", 0),
        ("spinning-ball", 1),
    ];
    common::snapshot_settings().bind(|| {
        for &(id, k) in cases {
            for law in RestitutionLaw::ALL {
                let lesson = with_law(Lesson::load(id).unwrap(), law);
                let text = stage_text(&trace(&lesson, k));
                insta::assert_snapshot!(format!("exact_stage@{id}-{k}-{}", Some(law).name()), text);
            }
        }
    });
}

/// The impulse-space figure: below the contact's picture in the SVG output
/// when the stage ran (never otherwise), alone as a snapshot.
#[test]
fn impulse_space_figure_in_the_svg_output() {
    use contact_lab::render::svg::{self, Plane};
    let rod = trace(&Lesson::load("rod-reverses").unwrap(), 0);
    let page = svg::render(&rod, Plane::Xy);
    assert!(page.contains(r#"height="1160" viewBox="0 0 1280 1160""#));
    assert!(page.contains("Impulse space (stronge restitution)"));
    assert!(page.contains(">halts, reverses</text>"));
    assert!(page.contains(">max compression</text>"));
    assert!(page.contains(">v_t1 (tangent t₁)</text>"));
    assert!(!page.contains(">v_t0 (tangent t₀)</text>"), "t₀ stays zero");
    let plain = svg::render(&trace(&Lesson::load("lecture-2").unwrap(), 0), Plane::Xy);
    assert!(plain.contains(r#"height="720""#));
    assert!(!plain.contains("Impulse space"));
    let alone = render::contact::impact::svg(&rod).unwrap();
    assert!(render::contact::impact::svg(&trace(&Lesson::load("lecture-2").unwrap(), 0)).is_none());
    common::snapshot_settings().bind(|| {
        insta::assert_snapshot!("exact_impulse_svg@rod-reverses", alone);
    });
}

/// Markdown with `--figures` writes the impulse-space figure beside the
/// contact's picture and links it in the stage.
#[test]
fn impulse_space_figure_in_markdown() {
    let dir = common::scratch("exact-figures");
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args([
            "solve",
            "kane-energy-gain",
            "--exact",
            "poisson",
            "--format",
            "md",
        ])
        .arg("--figures")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success());
    let md = String::from_utf8(out.stdout).unwrap();
    let impulse = dir.join("kane-energy-gain-contact-0-impulse.svg");
    let svg = std::fs::read_to_string(&impulse).unwrap();
    assert!(svg.contains("Impulse space (poisson restitution)"));
    assert!(svg.contains(">halts, sticks</text>"));
    let picture = std::fs::read_to_string(dir.join("kane-energy-gain-contact-0.svg")).unwrap();
    assert!(
        !picture.contains("Impulse space"),
        "the picture stays alone"
    );
    let stage = md.split("### 9. Exact impact integration").nth(1).unwrap();
    let stage = stage.split("### 10. Checks").next().unwrap();
    assert!(stage.contains("![Impulse space: u_n and u_t against P_n, the phase changes marked]("));
    assert!(stage.contains("kane-energy-gain-contact-0-impulse.svg)"));
    let _ = std::fs::remove_dir_all(&dir);
}
