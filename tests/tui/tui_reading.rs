//! What a class reads on the TUI is whole: no line break inside a number or
//! a unit, every cut list saying how much it hides, every event readable
//! in full, `s` scrolling to the symbols, the edit form's numbers through
//! the formatter; and Esc or q never losing edits or a predict score
//! without asking.

use crate::common::tui::{app, ctrl, draw, edit, key, keys, screen, term, text, type_text};

use contact_lab::tui::app::Mode;
use contact_lab::tui::screens::Screen;
use contact_lab::tui::{self, App, Theme};
use ratatui::crossterm::event::KeyCode;

/// Every lesson with contacts of its own (not a scene), with its index.
fn contact_lessons() -> Vec<(Vec<contact_lab::lesson::Lesson>, usize)> {
    let (all, _) = tui::lessons(None::<&str>).expect("lessons load");
    (0..all.len())
        .filter(|&i| all[i].simulation.is_none() && !all[i].contacts.is_empty())
        .map(|i| (all.clone(), i))
        .collect()
}

/// Every stage page of every contact of every lesson, at the stage panel's
/// widths at 80×24 and 100×30, with the symbols listed at the narrower
/// (they only add rows; listing them is slow in a debug build): each row of the panel is broken only at its spaces (so never
/// inside a number such as `0.0750194` or a unit such as `(m/s)/(N·s)`).
#[test]
fn no_line_break_falls_inside_a_number_or_a_unit() {
    let mut rows_checked = 0;
    for (lessons, at) in contact_lessons() {
        let contacts = lessons[at].contacts.len();
        let mut a = App::new(lessons, at, 0, Theme { color: false });
        let widths: Vec<u16> = [(80, 24), (100, 30)]
            .into_iter()
            .map(|(w, h)| {
                draw(&mut term(w, h), &a);
                a.panel_width.get()
            })
            .collect();
        let narrowest = widths.iter().copied().min();
        for k in 0..contacts {
            if k > 0 {
                key(&mut a, KeyCode::Tab);
            }
            for &width in &widths {
                a.panel_width.set(width);
                a.symbols = Some(width) == narrowest;
                for page in 0..a.pages() {
                    a.page = page;
                    for (row, pieces) in tui::stage::wrapped_rows(&a) {
                        let words: Vec<&str> =
                            pieces.iter().flat_map(|p| p.split_whitespace()).collect();
                        assert_eq!(
                            words,
                            row.split_whitespace().collect::<Vec<_>>(),
                            "{} contact {k} page {page} at {width} cells: a break inside a word:\n{}",
                            a.trace.lesson,
                            pieces.join("\n")
                        );
                        rows_checked += 1;
                    }
                }
            }
        }
    }
    assert!(rows_checked > 1000, "{rows_checked}");
}

/// The example: friction-cube's contact 1, stage 5, a page down,
/// at 100×30: `0.0750194` and `(m/s)/(N·s)` each on one line.
#[test]
fn friction_cubes_unit_impulse_formula_keeps_its_numbers_whole() {
    let (lessons, at) = tui::lessons(Some("friction-cube")).unwrap();
    let mut a = App::new(lessons, at, 1, Theme { color: false });
    keys(&mut a, KeyCode::Right, 5);
    let mut rows = screen(&a, 100, 30);
    key(&mut a, KeyCode::PageDown);
    rows.extend(screen(&a, 100, 30));
    let all = rows.join("\n");
    for whole in ["0.0750194", "(m/s)/(N·s)"] {
        assert!(all.contains(whole), "{whole} is not whole:\n{all}");
    }
    for piece in ["(0.07501 ", "(m/s)/(N "] {
        assert!(!all.contains(piece), "{piece} is broken:\n{all}");
    }
}

#[test]
fn esc_and_q_ask_before_losing_edits() {
    for quit in [KeyCode::Esc, KeyCode::Char('q')] {
        // Nothing to lose: quits at once.
        let mut a = app("lecture-2", false);
        key(&mut a, quit);
        assert!(a.quit);
        // An edit: asks; any other key stays, y quits.
        let mut a = app("lecture-2", false);
        edit(&mut a, "restitution", "0.5");
        key(&mut a, KeyCode::Esc); // closes the form
        assert_eq!(a.mode, Mode::Normal);
        key(&mut a, quit);
        assert!(!a.quit, "{quit:?} quit with an edit");
        let Mode::Quit(lost) = &a.mode else {
            panic!("{quit:?} does not ask: {:?}", a.mode)
        };
        assert!(lost.contains("lecture-2 (1 edit(s))"), "{lost}");
        let rows = screen(&a, 80, 24).join("\n");
        assert!(
            rows.contains("Quit? This loses the edits to lecture-2"),
            "{rows}"
        );
        key(&mut a, KeyCode::Char('n'));
        assert!(!a.quit);
        assert_eq!(a.mode, Mode::Normal);
        assert_eq!(a.entry().edits.len(), 1, "the edit is kept");
        key(&mut a, quit);
        key(&mut a, KeyCode::Char('y'));
        assert!(a.quit);
        // Ctrl-C quits at once.
        let mut a = app("lecture-2", false);
        edit(&mut a, "restitution", "0.5");
        key(&mut a, KeyCode::Esc);
        ctrl(&mut a, 'c');
        assert!(a.quit);
    }
}

#[test]
fn esc_asks_before_losing_a_predict_score() {
    let mut a = app("lecture-2", false);
    key(&mut a, KeyCode::Char('p'));
    key(&mut a, KeyCode::Right);
    type_text(&mut a, "(1, 2, 3)");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.score.graded, 1, "{:?}", a.mode);
    key(&mut a, KeyCode::Esc);
    assert!(!a.quit, "Esc quit with a predict score");
    let Mode::Quit(lost) = &a.mode else {
        panic!("Esc does not ask: {:?}", a.mode)
    };
    assert!(lost.contains("the predict score"), "{lost}");
}

/// A scene's resolver with more contacts than rows, and the lessons list
/// at 80×24: each says how many rows it hides.
#[test]
fn every_cut_list_says_how_much_it_hides() {
    let mut a = tui::open(Some("sphere-row-20"), None).unwrap();
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Resolver);
    let n = a.resolver.as_ref().unwrap().trace.world.contacts.len();
    assert!(n >= 20, "{n}");
    let rows = screen(&a, 80, 24).join("\n");
    assert!(
        rows.contains(" more below ") || rows.contains(" more above"),
        "{rows}"
    );
    let a = app("lecture-2", false);
    let rows = screen(&a, 80, 24).join("\n");
    assert!(rows.contains(" more below "), "{rows}");
}

/// `i` on the run: the events on show, each whole.
#[test]
fn every_event_can_be_read_whole() {
    let mut a = tui::open(Some("stack-5"), None).unwrap();
    key(&mut a, KeyCode::Char('n'));
    let mut t = term(80, 24);
    draw(&mut t, &a);
    let run = a.run.as_ref().unwrap();
    let (start, end) = run.events_shown.get();
    assert!(end > start, "events on show");
    let longest = run.player.run.events[start..end]
        .iter()
        .max_by_key(|e| e.text.len())
        .unwrap()
        .text
        .clone();
    assert!(!text(t.backend().buffer()).contains(&longest));
    key(&mut a, KeyCode::Char('i'));
    assert_eq!(a.mode, Mode::Events(0));
    let mut t = term(80, 24);
    draw(&mut t, &a);
    let shown = text(t.backend().buffer());
    for word in longest.split_whitespace() {
        assert!(shown.contains(word), "{word} not in\n{shown}");
    }
    key(&mut a, KeyCode::Char('x'));
    assert_eq!(a.mode, Mode::Normal);
}

/// `s` lists the symbols below the formulas: the panel scrolls to them.
#[test]
fn s_scrolls_to_the_symbols() {
    let (lessons, at) = tui::lessons(Some("friction-cube")).unwrap();
    let mut a = App::new(lessons, at, 1, Theme { color: false });
    keys(&mut a, KeyCode::Right, 5);
    let before = screen(&a, 80, 24).join("\n");
    key(&mut a, KeyCode::Char('s'));
    let after = screen(&a, 80, 24).join("\n");
    assert!(!before.contains("Symbols in these formulas"));
    assert!(after.contains("Symbols in these formulas"), "{after}");
    // Scrolled to the middle: the panel says what lies above and below.
    assert!(after.contains(" above · ↓ "), "{after}");
}

/// The form lists numbers as the formatter writes them; an edit that
/// changes nothing says why.
#[test]
fn the_edit_form_shows_formatted_numbers_and_says_why_nothing_changed() {
    let mut a = app("lecture-2", false);
    key(&mut a, KeyCode::Char('e'));
    let rows = screen(&a, 100, 30).join("\n");
    assert!(rows.contains("duration                1/100 s"), "{rows}");
    assert!(
        rows.contains("cube: velocity          (2.165, -1.25, 0) m/s"),
        "{rows}"
    );
    // A velocity limit above the closing speed forces restitution to 0:
    // restitution then changes nothing, and says why.
    key(&mut a, KeyCode::Esc);
    edit(&mut a, "velocity_limit", "100");
    key(&mut a, KeyCode::Esc);
    edit(&mut a, "restitution", "0.6");
    let said = &a.status.as_ref().expect("a status").text;
    assert!(said.contains("0 values changed"), "{said}");
    assert!(said.contains("velocity limit"), "{said}");
}
