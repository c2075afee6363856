//! One kind of minus sign (issue 16, item 9): no output of any lesson
//! contains U+2212, so a number or formula copied from it pastes into a
//! calculator. Text, Markdown, LaTeX, JSON, SVG (every plane and stage), the
//! TUI's screens (every page, every plane), the glossary, `check`, exercise
//! sheets, and every snapshot held in /snapshots.

use crate::common;

use contact_lab::format::Fmt;
use contact_lab::physics::StageId;
use contact_lab::render;
use contact_lab::render::figure::Plane;
use contact_lab::tui::{self, App, Theme};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

const MINUS: char = '\u{2212}';

#[track_caller]
fn ascii_minus(what: &str, out: &str) {
    if let Some(line) = out.lines().find(|l| l.contains(MINUS)) {
        panic!("{what}: U+2212 in «{line}»");
    }
}

#[test]
fn no_rendering_of_any_lesson_has_a_unicode_minus() {
    let fmt = Fmt::default();
    for lesson in common::all_lessons() {
        let id = &lesson.id;
        let traces: Vec<_> = (0..lesson.contacts.len())
            .map(|k| contact_lab::worked_solution(&lesson, k))
            .collect();
        ascii_minus(id, &render::contact::markdown::document(&traces, &fmt, &[]));
        ascii_minus(id, &render::contact::latex::document(&traces, &fmt, false));
        for t in &traces {
            ascii_minus(id, &render::contact::text::render(t, &fmt));
            ascii_minus(id, &render::contact::json::render(t));
            for plane in [Plane::Xy, Plane::Yz, Plane::Zx] {
                ascii_minus(id, &render::svg::render(t, plane));
                for stage in StageId::ALL {
                    ascii_minus(id, &render::svg::render_at(t, plane, Some(stage)));
                }
            }
        }
    }
    ascii_minus("glossary", &render::glossary::text());
}

#[test]
fn no_tui_screen_has_a_unicode_minus() {
    let mut t = Terminal::new(TestBackend::new(140, 45)).unwrap();
    for lesson in common::all_lessons() {
        let (lessons, at) = tui::lessons(Some(&lesson.id)).unwrap();
        let mut app = App::new(lessons, at, 0, Theme { color: false });
        for _ in 0..lesson.contacts.len() {
            for _plane in 0..3 {
                for page in 0..app.pages() {
                    app.page = page;
                    t.draw(|f| f.render_widget(&app, f.area())).unwrap();
                    let buf = t.backend().buffer();
                    let text: String = buf.content.iter().map(|c| c.symbol()).collect();
                    ascii_minus(&format!("{} page {page}", lesson.id), &text);
                }
                app.key(KeyEvent::new(KeyCode::Char('v'), KeyModifiers::NONE));
            }
            app.key(KeyEvent::new(KeyCode::Tab, KeyModifiers::NONE));
        }
    }
}

#[test]
fn no_command_output_or_snapshot_has_a_unicode_minus() {
    let run = |args: &[&str]| {
        let out = assert_cmd::Command::cargo_bin("contact-lab")
            .unwrap()
            .args(args)
            .output()
            .unwrap();
        ascii_minus(&args.join(" "), &String::from_utf8_lossy(&out.stdout));
        ascii_minus(&args.join(" "), &String::from_utf8_lossy(&out.stderr));
    };
    run(&["check"]);
    run(&["glossary"]);
    run(&["exercise", "--seed", "2", "--count", "5", "--answers"]);
    run(&[
        "exercise",
        "--seed",
        "2",
        "--count",
        "5",
        "--answers",
        "--format",
        "latex",
    ]);
    run(&["resolve", "box-four-corners"]);
    run(&["resolve", "box-four-corners", "--format", "md"]);
    run(&["simulate", "ball-drop", "--steps", "30"]);
    run(&["solve", "spinning-ball", "-c", "1", "--compare-friction"]);
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots");
    let mut files = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        ascii_minus(
            &path.display().to_string(),
            &std::fs::read_to_string(&path).unwrap(),
        );
        files += 1;
    }
    assert!(files > 100, "{files}");
}
