//! The resolver screen on a step of the soft step or XPBD: it says what it
//! shows and walks the step's own record (substeps, one contact's soft
//! coefficients or λ_n, Δλ_n, α̃), never the lecture's deepest-first phases
//! run silently; the record on show is the one the step itself keeps (the
//! same step run again with its record asked gives the same record), and
//! the screen prints its values.

use crate::common::tui::{draw, key, keys, term, text};

use contact_lab::format::Fmt;
use contact_lab::lesson::Lesson;
use contact_lab::physics::step::soft::SoftTrace;
use contact_lab::physics::step::Simulation;
use contact_lab::trace::substeps::SubstepsRecord;
use contact_lab::tui::screens::{breadcrumb, Screen};
use contact_lab::tui::{self, App, Theme};
use ratatui::crossterm::event::KeyCode;

/// stack-5 under `solver`, written to a file in `dir`.
fn stack_under(dir: &std::path::Path, solver: &str) -> std::path::PathBuf {
    let text = include_str!("../../lessons/scenes/stack-5.toml").replacen(
        "[world]",
        &format!("[settings]\nsolver = \"{solver}\"\n\n[world]"),
        1,
    );
    let path = dir.join(format!("stack-{solver}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

/// The app on `path`'s run, at frame `frame`, on that step's resolver.
fn resolver_at(path: &std::path::Path, frame: usize) -> App {
    let mut a = tui::open(Some(path.as_os_str()), None).expect("opens");
    a.theme = Theme { color: false };
    assert_eq!(a.screen, Screen::Run);
    keys(&mut a, KeyCode::Right, frame);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Resolver);
    a
}

/// The same step run again from the lesson with its record asked.
fn record_again(path: &std::path::Path, step: u64) -> Simulation<f64> {
    let lesson = Lesson::load(path.as_os_str()).unwrap();
    let params = lesson.sim_params().unwrap();
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    while sim.step < step - 1 {
        sim.advance().unwrap();
    }
    sim
}

fn screen_text(a: &App) -> String {
    let mut t = term(300, 60);
    draw(&mut t, a);
    text(t.backend().buffer())
}

#[test]
fn a_soft_step_frame_shows_its_own_substeps_and_soft_coefficients() {
    let dir = tempfile::tempdir().unwrap();
    let path = stack_under(dir.path(), "soft-step");
    let mut a = resolver_at(&path, 5);
    let r = a.resolver.as_ref().unwrap();
    let step = r.trace.step;
    let Some(SubstepsRecord::Soft(shown)) = r.trace.substeps.clone() else {
        panic!("no soft-step record on the resolver screen");
    };
    let mut sim = record_again(&path, step);
    sim.soft_trace = Some(SoftTrace::default());
    sim.advance().unwrap();
    assert_eq!(
        sim.soft_trace.as_ref(),
        Some(&shown),
        "not the step's record"
    );
    let screen = screen_text(&a);
    assert!(screen.contains("under the soft step"), "{screen}");
    assert!(screen.contains("Not the lecture's phases"), "{screen}");
    let f = Fmt::new(4);
    let k = a.resolver.as_ref().unwrap().selected;
    let c = &shown.contacts[k];
    for x in [c.bias_rate, c.mass_scale, c.impulse_scale, c.normal_impulse] {
        assert!(
            screen.contains(&f.num(x)),
            "{} not shown:\n{screen}",
            f.num(x)
        );
    }
    for p in &c.substep_impulses {
        assert!(
            screen.contains(&format!("P_n = {} N·s", f.num(*p))),
            "{screen}"
        );
    }
    assert_eq!(
        c.substep_impulses.len(),
        shown.substeps,
        "one impulse a substep"
    );
    for (w, h) in [(1, 1), (20, 5), (80, 24), (200, 60)] {
        draw(&mut term(w, h), &a);
    }
    // → moves the substep cursor; the breadcrumb says which.
    key(&mut a, KeyCode::Right);
    assert!(
        breadcrumb(&a).ends_with("soft step substep 2 of 4"),
        "{}",
        breadcrumb(&a)
    );
    // Enter does not open the lecture's stages for a soft-step contact.
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Resolver);
}

#[test]
fn an_xpbd_frame_shows_its_position_and_velocity_passes() {
    let dir = tempfile::tempdir().unwrap();
    let path = stack_under(dir.path(), "xpbd");
    let a = resolver_at(&path, 5);
    let r = a.resolver.as_ref().unwrap();
    let Some(SubstepsRecord::Xpbd(shown)) = r.trace.substeps.clone() else {
        panic!("no XPBD record on the resolver screen");
    };
    let mut sim = record_again(&path, r.trace.step);
    sim.xpbd_trace = Some(Vec::new());
    sim.advance().unwrap();
    assert_eq!(
        sim.xpbd_trace.as_ref(),
        Some(&shown),
        "not the step's record"
    );
    assert_eq!(shown.len(), 4);
    let screen = screen_text(&a);
    assert!(screen.contains("under XPBD"), "{screen}");
    let f = Fmt::new(4);
    let k = r.selected;
    let mut rows = 0;
    for s in &shown {
        for c in s.contacts.iter().filter(|c| c.contact == k) {
            assert!(
                screen.contains(&format!("Δλ_n = {} kg·m", f.num(c.delta_lambda))),
                "{screen}"
            );
            assert!(
                screen.contains(&format!("λ_n = {} kg·m", f.num(c.lambda))),
                "{screen}"
            );
            rows += 1;
        }
    }
    assert!(rows > 0, "contact {k} never penetrated in the record");
    assert!(screen.contains(&format!("α̃ = α/h² = {}", f.num(shown[0].alpha_tilde))));
}

#[test]
fn a_frame_under_the_lectures_order_keeps_its_phases() {
    let mut a = tui::open(Some("stack-5"), None).expect("opens");
    keys(&mut a, KeyCode::Right, 5);
    key(&mut a, KeyCode::Enter);
    assert!(a.resolver.as_ref().unwrap().trace.substeps.is_none());
}
