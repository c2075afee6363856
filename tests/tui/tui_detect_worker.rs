//! `d` on a scene with a huge hull (issue 39, item 6): one hull of
//! thousands of vertices is not a large scene by its bodies or contacts,
//! but its detection walks every vertex at every GJK and EPA iteration (a
//! hull of 100,000 vertices kept the UI thread over 10 s). The detection
//! goes to the worker: `d` returns with the run on show and a working line
//! counting the pairs done, Esc cancels, q quits, all while the worker may
//! still be running (its outcome is collected only by `tick`).

use std::time::{Duration, Instant};

use contact_lab::tui::screens::Screen;
use contact_lab::tui::{self, App, Theme};
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// A scene of one hull of `n` points on a sphere of radius 0.5 (every
/// point a vertex) resting on a floor.
fn hull_scene(n: usize) -> std::path::PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join(format!("worker-hull-{n}.toml"));
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let points: Vec<String> = (0..n)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - y * y).sqrt();
            let t = golden * i as f64;
            format!(
                "[{}, {}, {}]",
                0.5 * r * t.cos(),
                0.5 * y,
                0.5 * r * t.sin()
            )
        })
        .collect();
    let s = format!(
        "id = \"hull-{n}\"\ntitle = \"a hull of {n} points\"\nsource = \"test\"\nsummary = \"test\"\n\n[world]\ngravity = [0, -9.81, 0]\n\n[step]\ndt = 0.016666666666666666\nsteps = 10\n\n[[body]]\nname = \"ball\"\nmass = 1.0\nshape = {{ convex = [{}] }}\nposition = [0, 0.49, 0]\n\n[[body]]\nname = \"slab\"\nmass = inf\nshape = {{ box = [4, 0.2, 4] }}\nposition = [0, -0.1, 0]\n",
        points.join(", ")
    );
    std::fs::write(&path, s).unwrap();
    path
}

fn key(app: &mut App, code: KeyCode) {
    app.key(KeyEvent::new(code, KeyModifiers::NONE));
}

fn opened() -> App {
    let path = hull_scene(1_500);
    let mut app = tui::open(Some(path.as_os_str()), None).expect("opens");
    app.theme = Theme { color: false };
    let run = app.run.as_ref().unwrap();
    assert!(run.player.detects_later(), "a hull of 1,500 vertices");
    app
}

#[test]
fn d_on_a_huge_hull_detects_on_the_worker_and_counts_the_pairs() {
    let mut app = opened();
    key(&mut app, KeyCode::Char('d'));
    assert_eq!(app.screen, Screen::Run, "the run stays on show meanwhile");
    let detecting = app.run.as_ref().unwrap().detecting.clone();
    let (job, _) = detecting.expect("a detection under way");
    // No tick: the outcome is not collected, so the working line stays and
    // its count is the worker's (once it has counted the pairs).
    let start = Instant::now();
    while job.progress().is_none() && start.elapsed() < Duration::from_secs(120) {
        std::thread::sleep(Duration::from_millis(10));
    }
    assert_eq!(job.progress().map(|(_, total)| total), Some(1));
    let screen = crate::common::tui::screen(&app, 120, 30).join("\n");
    assert!(
        screen.contains("working: detecting step 0's contacts, ")
            && screen.contains(" of 1 pair ("),
        "{screen}"
    );
    // q while the detection is under way (or done and not collected) quits.
    key(&mut app, KeyCode::Char('q'));
    assert!(app.quit, "q quits");
}

#[test]
fn esc_cancels_a_huge_hull_s_detection() {
    let mut app = opened();
    key(&mut app, KeyCode::Char('d'));
    assert!(app.run.as_ref().unwrap().detecting.is_some());
    key(&mut app, KeyCode::Esc);
    assert!(!app.quit, "Esc cancels, it does not quit");
    let said = app.status.clone().expect("said").text;
    assert!(said.contains("cancelled: step 0's detection"), "{said}");
    assert!(app.run.as_ref().unwrap().detecting.is_none());
    app.tick(1.0);
    assert_eq!(app.screen, Screen::Run, "a cancelled detection never opens");
}
