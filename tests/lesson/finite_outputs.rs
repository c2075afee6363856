//! A validated lesson never produces a non-finite number (issue 17, item 1):
//! random lesson files across the whole accepted range of magnitudes (0 and
//! 1e-60 to 1e60, with the extremes themselves, every shape, explicit and
//! rotated tensors, immovable bodies, every model and setting) that pass the
//! validator give only finite values in the trace and in every output: text,
//! JSON, Markdown, LaTeX and the SVG figure in all three planes, and in
//! `resolve`'s text and JSON (the lesson's contacts resolved together).

use contact_lab::format::Fmt;
use contact_lab::lesson::{validate, Lesson};
use contact_lab::render::{self, svg::Plane};
use contact_lab::trace::{Trace, Value};
use proptest::prelude::*;

/// A number as a lesson file may hold it: 0, ordinary, anywhere in the
/// accepted range (log-uniform), or exactly at its ends.
fn magnitude() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        4 => -10.0..10.0f64,
        4 => (prop::bool::ANY, -60.0..60.0f64).prop_map(|(neg, e)| {
            let x = 10f64.powf(e);
            if neg { -x } else { x }
        }),
        1 => prop::sample::select(vec![1e60, -1e60, 1e-60, -1e-60, 1e-30, 1e30]),
    ]
}

fn positive() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => 0.01..100.0f64,
        3 => (-60.0..60.0f64).prop_map(|e| 10f64.powf(e)),
        1 => prop::sample::select(vec![1e60, 1e-60]),
    ]
}

fn vec3() -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(magnitude())
}

fn list(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:e}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// One body's TOML: `movable` decides the mass, the shape or tensor follows.
fn body(name: &'static str) -> impl Strategy<Value = String> {
    (
        prop::option::weighted(0.85, positive()),
        0..6usize,
        prop::array::uniform3(positive()),
        prop::array::uniform4(-1.0..1.0f64),
        (vec3(), vec3(), vec3(), vec3()),
        prop::array::uniform4(magnitude()),
    )
        .prop_map(move |(mass, shape, sizes, rot, (p, v, w, a), q)| {
            let mut out = format!("[[body]]\nname = \"{name}\"\n");
            match mass {
                None => {
                    out.push_str("mass = inf\nshape = \"half_space\"\n");
                    out.push_str(&format!("position = [{}]\n", list(&p)));
                    return out;
                }
                Some(m) => out.push_str(&format!("mass = {m:e}\n")),
            }
            let [x, y, z] = sizes;
            match shape {
                0 => out.push_str(&format!("shape = {{ sphere = {x:e} }}\n")),
                1 => out.push_str(&format!("shape = {{ hollow_sphere = {x:e} }}\n")),
                2 => out.push_str(&format!("shape = {{ box = [{}] }}\n", list(&sizes))),
                3 => out.push_str(&format!(
                    "shape = {{ cylinder = {{ radius = {x:e}, height = {y:e} }} }}\n"
                )),
                4 => out.push_str(&format!(
                    "inertia = [[{x:e}, 0.0, 0.0], [0.0, {y:e}, 0.0], [0.0, 0.0, {z:e}]]\n"
                )),
                _ => {
                    // Principal moments x, y, z in a rotated frame: a full tensor.
                    let r = nalgebra::UnitQuaternion::new_normalize(nalgebra::Quaternion::new(
                        rot[0] + 1.1,
                        rot[1],
                        rot[2],
                        rot[3],
                    ))
                    .to_rotation_matrix()
                    .into_inner();
                    let d = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(x, y, z));
                    let t = r * d * r.transpose();
                    let t = (t + t.transpose()) * 0.5;
                    let rows: Vec<String> = (0..3)
                        .map(|i| format!("[{}]", list(&[t[(i, 0)], t[(i, 1)], t[(i, 2)]])))
                        .collect();
                    out.push_str(&format!("inertia = [{}]\n", rows.join(", ")));
                }
            }
            out.push_str(&format!(
                "position = [{}]\norientation = [{}]\nvelocity = [{}]\nangular_velocity = [{}]\nacceleration = [{}]\n",
                list(&p),
                list(&q),
                list(&v),
                list(&w),
                list(&a)
            ));
            out
        })
}

fn contact() -> impl Strategy<Value = String> {
    (
        vec3(),
        vec3(),
        (magnitude(), 0.0..=1.0f64),
        (prop::option::of(positive()), prop::option::of(positive())),
        prop::sample::select(vec!["millington", "kinetic-direction", "velocity-scaling"]),
        (
            prop::sample::select(vec!["0.2", "inf", "0.0", "1e-60", "1e60"]),
            prop::sample::select(vec!["1.0", "0.5", "1e-60"]),
            prop::option::of(positive()),
            prop::option::of(positive()),
            prop::sample::select(vec!["linear", "nonlinear"]),
        ),
        prop::bool::ANY,
    )
        .prop_map(
            |(q, n, (pen, c), (mu_s, mu_d), model, (limit, relax, vlim, dur, proj), two)| {
                let mut out = String::from("[[contact]]\n");
                out.push_str(if two {
                    "bodies = [\"a\", \"b\"]\n"
                } else {
                    "bodies = [\"a\"]\n"
                });
                out.push_str(&format!(
                    "point = [{}]\nnormal = [{}]\npenetration = {pen:e}\nrestitution = {c:e}\n",
                    list(&q),
                    list(&n)
                ));
                if let Some(mu) = mu_s {
                    out.push_str(&format!("static_friction = {mu:e}\n"));
                }
                if let Some(mu) = mu_d {
                    out.push_str(&format!("dynamic_friction = {mu:e}\n"));
                }
                out.push_str(&format!("friction_model = \"{model}\"\n"));
                let mut s = format!(
                    "angular_limit = {limit}, relaxation = {relax}, projection = \"{proj}\""
                );
                if let Some(v) = vlim {
                    s.push_str(&format!(", velocity_limit = {v:e}"));
                }
                if let Some(d) = dur {
                    s.push_str(&format!(", duration = {d:e}"));
                }
                out.push_str(&format!("settings = {{ {s} }}\n"));
                out
            },
        )
}

fn lesson_text() -> impl Strategy<Value = String> {
    (body("a"), body("b"), prop::collection::vec(contact(), 1..3)).prop_map(|(a, b, cs)| {
        format!(
            "id = \"random\"\ntitle = \"Random\"\n\n{a}\n{b}\n{}",
            cs.join("\n")
        )
    })
}

fn finite(v: &Value) -> bool {
    match v {
        Value::Scalar(x) => x.is_finite(),
        Value::Vector(a) => a.iter().all(|x| x.is_finite()),
        Value::Quaternion(q) => q.iter().all(|x| x.is_finite()),
        Value::Matrix(m) => m.iter().flatten().all(|x| x.is_finite()),
        Value::Text(_) | Value::List(_) => true,
    }
}

/// `inf` as a word (not inside "infinite", "information", …).
fn shows_inf(text: &str) -> bool {
    text.split(|c: char| !c.is_alphanumeric())
        .any(|w| w == "inf" || w == "NaN")
}

fn check(lesson: &Lesson, k: usize, t: &Trace) -> Result<(), String> {
    let no_limit = lesson.contacts[k].settings.angular_limit.is_infinite();
    for step in &t.stages {
        for (name, v) in step.values.iter().chain(&step.inputs) {
            let allowed = no_limit && name.starts_with("angular_limit");
            if !allowed && !finite(v) {
                return Err(format!("{}.{name} = {v:?}", step.id.json_name()));
            }
        }
    }
    for s in [&t.after] {
        for (body, state) in s {
            if !format!("{state:?}")
                .split(|c: char| !c.is_alphanumeric())
                .all(|w| w != "NaN" && w != "inf")
            {
                return Err(format!("after {body}: {state:?}"));
            }
        }
    }
    let fmt = Fmt::default();
    let text = render::contact::text::render(t, &fmt);
    let md = render::contact::markdown::document(std::slice::from_ref(t), &fmt, &[]);
    let latex = render::contact::latex::document(std::slice::from_ref(t), &fmt, false);
    for (what, out) in [("text", &text), ("markdown", &md), ("latex", &latex)] {
        if out.contains("NaN") || (!no_limit && shows_inf(out)) {
            return Err(format!("{what} shows NaN or inf:\n{out}"));
        }
    }
    let json = render::contact::json::render(t);
    if json.matches("null").count() != json.matches("\"skipped\": null").count() {
        return Err(format!("JSON has a non-finite number (null):\n{json}"));
    }
    for plane in [Plane::Xy, Plane::Yz, Plane::Zx] {
        let svg = render::svg::render(t, plane);
        let doc = roxmltree::Document::parse(&svg).map_err(|e| format!("SVG: {e}"))?;
        for node in doc.descendants() {
            for a in node.attributes() {
                let bad = a.value().contains("NaN")
                    || a.value()
                        .split([' ', ',', '(', ')'])
                        .any(|w| w.parse::<f64>().is_ok_and(|x| !x.is_finite()));
                if bad {
                    return Err(format!("SVG ({plane:?}) {}=\"{}\"", a.name(), a.value()));
                }
            }
            if let Some(text) = node.text() {
                if text.contains("NaN") || (!no_limit && shows_inf(text)) {
                    return Err(format!("SVG ({plane:?}) text «{text}»"));
                }
            }
        }
    }
    Ok(())
}

/// `resolve` of the lesson (its contacts together, with the log) in text
/// and JSON: no NaN, no inf, no null, unless `resolve`'s guard refuses the
/// lesson first.
fn check_resolve(lesson: &Lesson) -> Result<(), String> {
    use contact_lab::physics::resolver::Implementation;
    let guard = contact_lab::lesson::overflow::check_resolve(
        lesson,
        &lesson.resolver,
        Implementation::Indexed,
    );
    if guard.is_err() {
        // `resolve` refuses it (exit 1) rather than print NaN.
        return Ok(());
    }
    let trace = contact_lab::trace::resolver::describe(
        lesson,
        &lesson.resolver,
        Implementation::Indexed,
        true,
    );
    let text = render::resolve::text::render(&trace, &Fmt::default());
    let no_limit = lesson
        .contacts
        .iter()
        .any(|c| c.settings.angular_limit.is_infinite());
    if text.contains("NaN") || (!no_limit && shows_inf(&text)) {
        return Err(format!("text shows NaN or inf:\n{text}"));
    }
    let json = render::resolve::json::render(&trace, &Default::default(), true);
    if json.contains("null") || json.contains("NaN") {
        return Err(format!("JSON has a non-finite number:\n{json}"));
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 300,
        max_global_rejects: 20_000,
        ..ProptestConfig::default()
    })]

    #[test]
    fn every_validated_lesson_gives_only_finite_outputs(text in lesson_text()) {
        let parsed = validate::parse("random.toml", &text);
        prop_assume!(parsed.is_ok());
        let lesson = parsed.unwrap();
        for k in 0..lesson.contacts.len() {
            let t = contact_lab::worked_solution(&lesson, k);
            if let Err(e) = check(&lesson, k, &t) {
                prop_assert!(false, "contact {}: {}\n--- lesson ---\n{}", k, e, text);
            }
        }
        if let Err(e) = check_resolve(&lesson) {
            prop_assert!(false, "resolve: {}\n--- lesson ---\n{}", e, text);
        }
    }
}

/// The generator reaches the validator's far corners often enough that the
/// property above is not vacuous.
#[test]
fn the_random_lessons_validate_often_enough() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = lesson_text();
    let (mut valid, mut extreme, mut resolved) = (0, 0, 0);
    for _ in 0..400 {
        let text = strategy.new_tree(&mut runner).unwrap().current();
        if let Ok(l) = validate::parse("random.toml", &text) {
            valid += 1;
            let big = |x: f64| x != 0.0 && !(1e-20..1e20).contains(&x.abs());
            if l.bodies
                .iter()
                .any(|b| b.velocity.iter().chain(b.position.iter()).any(|x| big(*x)))
            {
                extreme += 1;
            }
            let implementation = contact_lab::physics::resolver::Implementation::Indexed;
            if contact_lab::lesson::overflow::check_resolve(&l, &l.resolver, implementation).is_ok()
            {
                resolved += 1;
            }
        }
    }
    println!(
        "{valid} of 400 random lessons validate, {extreme} beyond 1e±20, {resolved} pass resolve's guard"
    );
    assert!(valid >= 40, "only {valid} of 400 random lessons validate");
    assert!(
        extreme >= 20,
        "only {extreme} valid lessons reach beyond 1e±20"
    );
    assert!(
        resolved * 10 >= valid * 8,
        "resolve's guard refuses {} of {valid} valid lessons",
        valid - resolved
    );
}
