//! The TUI driven by scripted keys into a `TestBackend` (gitui style): screen
//! snapshots at 100×30 and 80×24, style assertions where highlighting
//! matters, every lesson at every size without a panic, refused edits.

use crate::common;
use crate::common::tui::{
    app, ctrl, draw, edit, find, key, row, snapshot, term, text as buffer_text, type_text,
};

use contact_lab::trace::Value;
use contact_lab::tui::app::Mode;
use contact_lab::tui::{self, App};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::style::{Color, Modifier};
use ratatui::Terminal;

const SIZES: [(u16, u16); 2] = [(100, 30), (80, 24)];

fn impulse(app: &App) -> f64 {
    match app.trace.value("impulse", "impulse_world") {
        Some(Value::Vector(v)) => v[1],
        other => panic!("impulse_world: {other:?}"),
    }
}

#[test]
fn step_through_every_stage_of_lecture_2() {
    for (w, h) in SIZES {
        let mut a = app("lecture-2", true);
        let mut t = term(w, h);
        for page in 0..a.pages() {
            draw(&mut t, &a);
            assert_eq!(a.page, page);
            snapshot(&format!("tui_lecture-2_{w}x{h}_page{page}"), &t);
            key(&mut a, KeyCode::Right);
        }
        assert_eq!(a.page, a.pages() - 1, "→ stops at the last stage");
    }
}

/// The exact impact stage in the stage panel: a lesson that asks for it.
#[test]
fn the_exact_impact_stage_shows_in_the_panel() {
    let mut a = app("rod-reverses", true);
    let mut t = term(100, 30);
    for _ in 0..9 {
        key(&mut a, KeyCode::Right);
    }
    draw(&mut t, &a);
    let text = buffer_text(t.backend().buffer());
    assert!(text.contains("9/10 Exact impact integration"), "{text}");
    assert!(text.contains("9 Integration"));
    assert!(!text.contains("9 Integration · skipped"));
    snapshot("tui_rod-reverses_exact_100x30", &t);
    // Further down the panel: the phases.
    for _ in 0..3 {
        key(&mut a, KeyCode::PageDown);
    }
    draw(&mut t, &a);
    let text = buffer_text(t.backend().buffer());
    assert!(
        text.contains("reverses") || text.contains("slips back"),
        "{text}"
    );
}

#[test]
fn editing_restitution_to_half_changes_the_impulse() {
    for (w, h) in SIZES {
        let mut a = app("lecture-2", true);
        let mut t = term(w, h);
        let before = impulse(&a);
        edit(&mut a, "restitution", "0.5");
        draw(&mut t, &a);
        snapshot(&format!("tui_edit_restitution_form_{w}x{h}"), &t);
        let after = impulse(&a);
        // Δv = 1.5 · 1.25 instead of 1.8 · 1.25: the impulse scales by 1.5 / 1.8.
        assert!(
            (after / before - 1.5 / 1.8).abs() < 1e-12,
            "{before} → {after}"
        );
        key(&mut a, KeyCode::Esc);
        assert_eq!(a.mode, Mode::Normal);
        for _ in 0..4 {
            key(&mut a, KeyCode::Right);
        }
        draw(&mut t, &a);
        snapshot(&format!("tui_edit_restitution_impulse_{w}x{h}"), &t);
        // The changed result is marked and styled as changed.
        let buf = t.backend().buffer();
        let (x, y) = find(buf, "= 15.6114");
        assert_eq!(buf[(x, y)].fg, Color::Yellow);
        assert!(buf[(x, y)].modifier.contains(Modifier::UNDERLINED));
        let mark = row(buf, y);
        assert!(mark.contains('●'), "changed line has a marker: {mark}");
        // r restores the lesson's values.
        key(&mut a, KeyCode::Char('r'));
        assert_eq!(impulse(&a), before);
        assert!(a.entry().edits.is_empty());
    }
}

#[test]
fn refused_edits_keep_the_old_value() {
    let mut a = app("lecture-2", true);
    let trace = a.trace.clone();
    let mut t = term(80, 24);
    edit(&mut a, "cube: mass", "NaN");
    draw(&mut t, &a);
    snapshot("tui_edit_refused_nan_mass_80x24", &t);
    let Mode::Edit(form) = &a.mode else {
        panic!("the form stays open")
    };
    assert!(form.error.as_deref().unwrap().contains("mass must be > 0"));
    assert_eq!(
        form.input.as_deref(),
        Some("NaN"),
        "the typed text stays to correct"
    );
    for bad in ["-10", "0", "inf"] {
        ctrl(&mut a, 'u');
        type_text(&mut a, bad);
        key(&mut a, KeyCode::Enter);
        let Mode::Edit(form) = &a.mode else { panic!() };
        assert!(form.error.is_some(), "mass {bad} is refused");
    }
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Esc);
    edit(&mut a, "restitution", "nan");
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Esc);
    edit(&mut a, "cube: velocity", "1, NaN, 0");
    let Mode::Edit(form) = &a.mode else { panic!() };
    assert!(form.error.as_deref().unwrap().contains("finite"));
    assert_eq!(a.entry().lesson.bodies[0].mass, 10.0);
    assert_eq!(a.entry().lesson.contacts[0].restitution, 0.8);
    assert!(a.entry().edits.is_empty());
    assert_eq!(a.trace, trace, "nothing was solved again");
}

#[test]
fn predict_mode_hides_results_until_revealed() {
    for (w, h) in SIZES {
        let mut a = app("lecture-2", true);
        let mut t = term(w, h);
        for _ in 0..3 {
            key(&mut a, KeyCode::Right);
        }
        key(&mut a, KeyCode::Char('p'));
        draw(&mut t, &a);
        snapshot(&format!("tui_predict_hidden_{w}x{h}"), &t);
        let buf = t.backend().buffer();
        let (x, y) = find(buf, "= ?");
        assert_eq!(
            buf[(x + 2, y)].fg,
            Color::Magenta,
            "the hidden result stands out"
        );
        assert!(
            !buffer_text(buf).contains("= -1.25"),
            "q̇₁ · d̂ is not shown yet"
        );
        let _ = find(buf, "Hidden in predict mode");
        // Space reveals one result at a time, then moves on.
        key(&mut a, KeyCode::Char(' '));
        key(&mut a, KeyCode::Char(' '));
        draw(&mut t, &a);
        snapshot(&format!("tui_predict_two_revealed_{w}x{h}"), &t);
        let formulas = a.trace.stages[2].formulas.len();
        for _ in 2..formulas {
            key(&mut a, KeyCode::Char(' '));
        }
        assert_eq!(a.page, 3, "still on the stage until all is revealed");
        key(&mut a, KeyCode::Char(' '));
        assert_eq!(a.page, 4, "then Space moves on");
    }
}

#[test]
fn help_overlay_lists_every_key() {
    for (w, h) in SIZES {
        let mut a = app("lecture-2", true);
        let mut t = term(w, h);
        key(&mut a, KeyCode::Char('?'));
        draw(&mut t, &a);
        snapshot(&format!("tui_help_{w}x{h}"), &t);
        let text = buffer_text(t.backend().buffer());
        for (k, _) in contact_lab::tui::keys::help(contact_lab::tui::event::KEYS) {
            assert!(text.contains(k), "help lists {k}");
        }
        key(&mut a, KeyCode::Char('x'));
        assert_eq!(a.mode, Mode::Normal, "any key closes help");
        assert!(!a.quit);
    }
}

#[test]
fn highlighting_marks_the_current_stage_skipped_stages_and_results() {
    let mut a = app("lecture-2", true);
    let mut t = term(100, 30);
    for _ in 0..4 {
        key(&mut a, KeyCode::Right);
    }
    draw(&mut t, &a);
    let buf = t.backend().buffer();
    let (x, y) = find(buf, "4 Impulse");
    assert!(
        buf[(x, y)].modifier.contains(Modifier::REVERSED),
        "current stage"
    );
    let (x, y) = find(buf, "5 Friction");
    assert_eq!(buf[(x, y)].fg, Color::DarkGray, "skipped stage dimmed");
    assert!(!buf[(x, y)].modifier.contains(Modifier::REVERSED));
    let (x, y) = find(buf, "= 18.7337");
    assert_eq!(buf[(x + 2, y)].fg, Color::Green, "result");
    let (x, y) = find(buf, "✓");
    assert_eq!(buf[(x, y)].fg, Color::Green, "passed check");
}

#[test]
fn no_color_draws_without_colours() {
    let mut a = app("two-boxes", false);
    let mut t = term(100, 30);
    for keys in [vec![], vec![KeyCode::End], vec![KeyCode::Char('?')]] {
        for k in keys {
            key(&mut a, k);
        }
        draw(&mut t, &a);
        let buf = t.backend().buffer();
        for cell in &buf.content {
            assert_eq!(cell.fg, Color::Reset, "fg colour with NO_COLOR");
            assert_eq!(cell.bg, Color::Reset, "bg colour with NO_COLOR");
        }
    }
    // The current stage is still marked, by reversing.
    key(&mut a, KeyCode::Esc);
    draw(&mut t, &a);
    let buf = t.backend().buffer();
    let (x, y) = find(buf, "▶  10 Checks");
    assert!(buf[(x + 3, y)].modifier.contains(Modifier::REVERSED));
}

#[test]
fn every_lesson_draws_at_every_size_without_panic() {
    let widths = [
        1, 2, 3, 7, 20, 40, 59, 60, 61, 79, 80, 99, 100, 101, 140, 200,
    ];
    let heights = [1, 2, 3, 5, 10, 17, 18, 19, 23, 24, 30, 45, 60];
    for lesson in common::all_lessons() {
        let mut a = app(&lesson.id, true);
        for k in 0..lesson.contacts.len() {
            let mut t = term(1, 1);
            for &w in &widths {
                for &h in &heights {
                    // Resize the same terminal, as a user would.
                    t.backend_mut().resize(w, h);
                    for page in [0, 1, a.pages() / 2, a.pages() - 1] {
                        a.page = page;
                        draw(&mut t, &a);
                    }
                    a.zoom = true;
                    draw(&mut t, &a);
                    a.zoom = false;
                }
            }
            for mode in [KeyCode::Char('?'), KeyCode::Char('e'), KeyCode::Char('w')] {
                key(&mut a, mode);
                for (w, h) in [(1, 1), (60, 18), (200, 60), (80, 24)] {
                    t.backend_mut().resize(w, h);
                    draw(&mut t, &a);
                }
                key(&mut a, KeyCode::Esc);
            }
            for plane in 0..3 {
                key(&mut a, KeyCode::Char('v'));
                t.backend_mut().resize(80 + plane, 24);
                draw(&mut t, &a);
            }
            key(&mut a, KeyCode::Tab);
            assert_eq!(a.contact, (k + 1) % lesson.contacts.len());
        }
    }
}

#[test]
fn too_small_says_so() {
    let a = app("lecture-2", true);
    let mut t = term(59, 24);
    draw(&mut t, &a);
    let text = buffer_text(t.backend().buffer());
    assert!(text.contains("Terminal too small: 59×24"), "{text}");
}

#[test]
fn keys_move_between_lessons_contacts_and_stages() {
    let mut a = app("lecture-2", true);
    key(&mut a, KeyCode::End);
    assert_eq!(a.page, a.pages() - 1);
    key(&mut a, KeyCode::Home);
    assert_eq!(a.page, 0);
    key(&mut a, KeyCode::Char('l'));
    key(&mut a, KeyCode::Char('l'));
    key(&mut a, KeyCode::Char('h'));
    assert_eq!(a.page, 1);
    key(&mut a, KeyCode::Char(']'));
    assert_eq!(a.trace.lesson, "lecture-3");
    assert_eq!(a.page, 0, "a new lesson opens on its overview");
    key(&mut a, KeyCode::Char('['));
    key(&mut a, KeyCode::Char('['));
    assert_eq!(a.trace.lesson, "lecture-1");
    key(&mut a, KeyCode::Char('['));
    // The list holds the lessons, then the scenes: wrapping around opens the
    // last scene on its run.
    let last = *contact_lab::lesson::embedded::scene_ids().last().unwrap();
    assert_eq!(a.entry().lesson.id, last, "wraps around");
    assert_eq!(a.screen, contact_lab::tui::screens::Screen::Run);
    let mut a = app("spinning-ball", true);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Tab);
    assert_eq!((a.contact, a.trace.contact, a.page), (1, 1, 1));
    key(&mut a, KeyCode::BackTab);
    assert_eq!(a.contact, 0);
    key(&mut a, KeyCode::Char('v'));
    assert_eq!(a.plane.name(), "yz");
    for quit in [
        KeyEvent::new(KeyCode::Char('q'), KeyModifiers::NONE),
        KeyEvent::new(KeyCode::Esc, KeyModifiers::NONE),
        KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL),
    ] {
        let mut a = app("lecture-1", true);
        a.key(quit);
        assert!(a.quit, "{quit:?} quits");
    }
}

#[test]
fn write_makes_a_markdown_file_and_asks_before_overwriting() {
    let dir = std::env::temp_dir().join(format!("contact-lab-tui-write-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut a = app("lecture-2", true);
    a.write_dir = dir.clone();
    let file = dir.join("lecture-2-contact-0.md");
    key(&mut a, KeyCode::Char('w'));
    key(&mut a, KeyCode::Enter);
    let first = std::fs::read_to_string(&file).expect("written");
    assert!(first.starts_with("# Cube hits the floor"));
    assert!(first.contains("&= (0, 18.7337, 0)"), "{first}");
    assert_eq!(
        a.status.as_ref().unwrap().text,
        format!("wrote {}", file.display())
    );
    // Edit, write again: the file exists, so the app asks; n keeps it.
    edit(&mut a, "restitution", "0.5");
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('w'));
    key(&mut a, KeyCode::Enter);
    assert!(matches!(a.mode, Mode::Confirm(_)));
    let mut t = term(80, 24);
    draw(&mut t, &a);
    snapshot("tui_write_confirm_80x24", &t);
    key(&mut a, KeyCode::Char('n'));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), first);
    // y overwrites, and the file says what was edited.
    key(&mut a, KeyCode::Char('w'));
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('y'));
    let second = std::fs::read_to_string(&file).unwrap();
    assert!(second.contains("- restitution 0.8 → 0.5"), "{second}");
    assert!(second.contains("&= (0, 15.6114, 0)"), "{second}");
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 1, "no temporary file left: {names:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn without_a_terminal_the_bare_command_prints_the_lesson_list() {
    let out = assert_cmd::Command::cargo_bin("contact-lab")
        .unwrap()
        .assert()
        .success();
    let text = String::from_utf8_lossy(&out.get_output().stdout).into_owned();
    assert!(text.contains("lecture-2"), "{text}");
}

#[test]
fn tui_subcommand_needs_a_terminal() {
    assert_cmd::Command::cargo_bin("contact-lab")
        .unwrap()
        .args(["tui", "lecture-2"])
        .assert()
        .code(2)
        .stderr(predicates::str::contains("the TUI needs a terminal"));
    assert_cmd::Command::cargo_bin("contact-lab")
        .unwrap()
        .args(["tui", "no-such-lesson"])
        .assert()
        .code(66);
    assert_cmd::Command::cargo_bin("contact-lab")
        .unwrap()
        .args(["tui", "lecture-2", "--contact", "3"])
        .assert()
        .code(2)
        .stderr(predicates::str::contains("--contact 3"));
}

#[test]
fn docs_tui_lists_every_tui_key() {
    let keys_page = include_str!("../../docs/tui.md");
    for (k, what) in contact_lab::tui::keys::help(contact_lab::tui::event::KEYS) {
        assert!(
            keys_page.contains(&format!("| {k} | {what} |")),
            "docs/tui.md lacks {k}"
        );
    }
}

#[test]
fn predict_mode_hides_the_narrative_that_quotes_results() {
    let mut app = tui::open(Some("lecture-2"), None).unwrap();
    let mut terminal = Terminal::new(TestBackend::new(200, 60)).unwrap();
    terminal.draw(|f| f.render_widget(&app, f.area())).unwrap();
    assert!(buffer_text(terminal.backend().buffer()).contains("(18.73 N·s)"));
    app.key(KeyEvent::from(KeyCode::Char('p')));
    terminal.draw(|f| f.render_widget(&app, f.area())).unwrap();
    let text = buffer_text(terminal.backend().buffer());
    assert!(!text.contains("(18.73 N·s)"), "{text}");
    assert!(text.contains("hidden in predict mode"));
}

/// A 3,000-character input scrolls on its one line: its end and the cursor
/// stay in view, and so does the refusal (which quotes only the start).
#[test]
fn a_3000_character_input_scrolls_and_its_refusal_stays_in_view() {
    let long = "7".repeat(2999) + "x";
    for (w, h) in SIZES {
        let mut app = app("lecture-2", false);
        let mut t = term(w, h);
        key(&mut app, KeyCode::Char('e'));
        key(&mut app, KeyCode::Enter);
        ctrl(&mut app, 'u');
        type_text(&mut app, &long);
        draw(&mut t, &app);
        let text = buffer_text(t.backend().buffer());
        assert!(
            text.contains("restitution (number) = …777"),
            "{w}×{h}:\n{text}"
        );
        assert!(
            text.contains("77x▏"),
            "the end and the cursor, {w}×{h}:\n{text}"
        );
        key(&mut app, KeyCode::Enter);
        draw(&mut t, &app);
        let text = buffer_text(t.backend().buffer());
        assert!(
            text.contains("77x▏"),
            "input after the refusal, {w}×{h}:\n{text}"
        );
        assert!(
            text.contains("refused: restitution: '7777"),
            "{w}×{h}:\n{text}"
        );
        assert!(text.contains("7…' is"), "{w}×{h}:\n{text}");
        assert!(text.contains("not a number"), "{w}×{h}:\n{text}");
        assert!(
            !text.contains(&"7".repeat(200)),
            "the refusal quotes only the start"
        );
    }
}

/// The same for the file name of `w`, and its error.
#[test]
fn a_3000_character_file_name_scrolls_and_its_error_stays_in_view() {
    let dir = common::scratch("long-name");
    let mut app = app("lecture-2", false);
    app.write_dir = dir.clone();
    let mut t = term(80, 24);
    key(&mut app, KeyCode::Char('w'));
    ctrl(&mut app, 'u');
    type_text(&mut app, &("n".repeat(2999) + "Z"));
    draw(&mut t, &app);
    let text = buffer_text(t.backend().buffer());
    assert!(text.contains("file: …nnn"), "{text}");
    assert!(text.contains("nnZ▏"), "{text}");
    key(&mut app, KeyCode::Enter);
    draw(&mut t, &app);
    let text = buffer_text(t.backend().buffer());
    assert!(text.contains("nnZ▏"), "{text}");
    assert!(text.contains("cannot write: File name too long"), "{text}");
}

#[test]
fn every_bound_key_does_what_its_help_row_says() {
    use contact_lab::tui::event::{action, KEYS};
    use ratatui::crossterm::event::{KeyEvent, KeyModifiers};
    // One table dispatches and prints the help: each key of a row acts as the row binds it,
    // and a key no row binds does nothing.
    for row in KEYS {
        for (code, bound) in row.keys {
            let got = action(KeyEvent::new(*code, KeyModifiers::NONE));
            assert_eq!(got, Some(*bound), "{} ({:?})", row.label, code);
        }
    }
    assert_eq!(
        action(KeyEvent::new(KeyCode::Char('x'), KeyModifiers::NONE)),
        None
    );
}
