//! The TUI as a teacher (issue #16): the stage's "why" above its formulas,
//! the picture at the stage, help's glossary page, the symbols panel, and
//! predict-mode answers typed, graded and scored. Scripted keys into a
//! `TestBackend`.

use crate::common::tui::{self as tui_helpers, key, row_of, screen, type_text};
use contact_lab::tui::app::Mode;
use contact_lab::tui::{self, App, Theme};
use ratatui::crossterm::event::KeyCode;

fn app(lesson: &str) -> App {
    tui_helpers::app(lesson, false)
}

/// Goes to stage `n` (1-based) of the open contact.
fn stage(app: &mut App, n: usize) {
    key(app, KeyCode::Home);
    for _ in 0..n {
        key(app, KeyCode::Right);
    }
}

#[test]
fn each_stage_says_why_above_its_formulas() {
    let mut a = app("lecture-2");
    stage(&mut a, 1);
    let rows = screen(&a, 100, 30);
    let why = row_of(&rows, "An impulse is easiest to find").expect("why sentence shown");
    let formula = row_of(&rows, "t₀ = ").expect("first formula shown");
    assert!(why < formula, "why at row {why}, formula at row {formula}");
    stage(&mut a, 4);
    let rows = screen(&a, 100, 30);
    assert!(row_of(&rows, "Dividing the change we want").is_some());
}

#[test]
fn the_picture_shows_the_state_its_stage_works_on() {
    let mut a = app("lecture-2");
    // Legend: the impulse appears at stage 4; after-velocities when stage 6
    // applies it; before-velocities go once it has been applied.
    let legend = |a: &mut App, n: usize| {
        stage(a, n);
        screen(a, 100, 30).join("\n")
    };
    let s1 = legend(&mut a, 1);
    assert!(s1.contains("v before") && !s1.contains("g impulse") && !s1.contains("v′ after"));
    let s4 = legend(&mut a, 4);
    assert!(s4.contains("g impulse") && s4.contains("v before") && !s4.contains("v′ after"));
    let s6 = legend(&mut a, 6);
    assert!(s6.contains("v before") && s6.contains("v′ after"));
    let s9 = legend(&mut a, 9);
    assert!(s9.contains("v′ after") && !s9.contains("v before"), "{s9}");
}

#[test]
fn help_has_a_second_page_with_the_glossary() {
    let mut a = app("lecture-2");
    key(&mut a, KeyCode::Char('?'));
    assert_eq!(a.mode, Mode::Help);
    key(&mut a, KeyCode::Char('?'));
    assert_eq!(a.mode, Mode::Glossary(0));
    let rows = screen(&a, 100, 30).join("\n");
    assert!(rows.contains("Glossary (2/2)"), "{rows}");
    assert!(rows.contains("contact normal, unit vector pointing from body 2 toward body 1"));
    assert!(rows.contains("n in the collisions lectures"), "{rows}");
    // It scrolls, no further than its end, and j/k do not switch lessons meanwhile.
    let lesson = a.lesson;
    for _ in 0..200 {
        key(&mut a, KeyCode::Char('j'));
    }
    let Mode::Glossary(at) = a.mode else {
        panic!("still on the glossary")
    };
    assert!(at > 0 && at == a.glossary_max.get(), "scrolled {at}");
    let rows = screen(&a, 100, 30).join("\n");
    assert!(
        rows.contains("kinetic energy of the bodies"),
        "the last symbol: {rows}"
    );
    assert_eq!(a.lesson, lesson);
    key(&mut a, KeyCode::Char('x'));
    assert_eq!(a.mode, Mode::Normal);
}

#[test]
fn s_lists_the_symbols_of_the_formulas_with_meaning_and_unit() {
    let mut a = app("lecture-2");
    stage(&mut a, 2);
    key(&mut a, KeyCode::Char('z')); // the stage panel alone is taller
    key(&mut a, KeyCode::Char('z'));
    key(&mut a, KeyCode::Char('s'));
    assert!(a.symbols);
    // Scroll to the end of the panel (as drawn), where the list is.
    screen(&a, 120, 60);
    for _ in 0..20 {
        key(&mut a, KeyCode::PageDown);
    }
    let rows = screen(&a, 120, 60).join("\n");
    assert!(rows.contains("Symbols in these formulas"), "{rows}");
    assert!(
        rows.contains("Δṗ_d: change of linear velocity per unit impulse"),
        "{rows}"
    );
    assert!(rows.contains("[(m/s)/(N·s)]"), "{rows}");
    key(&mut a, KeyCode::Char('s'));
    let rows = screen(&a, 120, 60).join("\n");
    assert!(!rows.contains("Symbols in these formulas"));
}

#[test]
fn predict_answers_are_graded_and_scored() {
    let mut a = app("lecture-2");
    // Outside predict mode a digit does nothing.
    stage(&mut a, 4);
    key(&mut a, KeyCode::Char('1'));
    assert_eq!(a.mode, Mode::Normal);
    key(&mut a, KeyCode::Char('p'));
    stage(&mut a, 4);
    // g = 18.7337 N·s: 18.73 is within the lecture check's tolerance.
    type_text(&mut a, "18.73");
    assert!(matches!(&a.mode, Mode::Answer { input, .. } if input == "18.73"));
    let rows = screen(&a, 100, 30);
    assert!(rows[29].contains("your answer: 18.73"), "{}", rows[29]);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.mode, Mode::Normal);
    assert_eq!((a.score.correct, a.score.graded), (1, 1), "{:?}", a.status);
    assert_eq!(a.revealed[3], 1, "the graded result is revealed");
    let said = a.status.clone().expect("a verdict").text;
    assert!(said.starts_with("✓ right: 18.7337 N·s"), "{said}");
    assert!(said.contains("18.7337 N·s, difference 0.0037"), "{said}");
    assert!(said.contains("; yours 18.73 · score"), "{said}");
    let rows = screen(&a, 100, 30);
    assert!(rows[0].contains("[predict 1/1]"), "{}", rows[0]);
    // g_contact = (18.7337, 0, 0): a wrong vector is graded wrong, with the difference.
    type_text(&mut a, "(18.7, 1, 0)");
    key(&mut a, KeyCode::Enter);
    assert_eq!((a.score.correct, a.score.graded), (1, 2));
    let s = a.status.clone().unwrap();
    assert!(s.error, "a wrong answer is shown as one");
    assert!(
        s.text.starts_with("✗ off: (18.7337, 0, 0) N·s"),
        "{}",
        s.text
    );
    assert!(
        s.text.contains("difference (0.0337046, -1, 0) N·s"),
        "{}",
        s.text
    );
    // At 80 columns the status row keeps the verdict and the difference.
    let rows = screen(&a, 80, 24);
    assert!(
        rows[23].contains("✗ off: (18.7337, 0, 0) N·s, difference (0.0337046, -1, 0)"),
        "{}",
        rows[23]
    );
    // An answer that cannot be compared is refused, not scored, and stays open.
    type_text(&mut a, "1 2");
    key(&mut a, KeyCode::Enter);
    assert!(
        matches!(&a.mode, Mode::Answer { error: Some(e), .. } if e.contains("3 numbers expected")),
        "{:?}",
        a.mode
    );
    assert_eq!(a.score.graded, 2);
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.mode, Mode::Normal);
    assert_eq!(a.revealed[3], 2, "Esc reveals nothing");
    // Another lesson starts a new score.
    key(&mut a, KeyCode::Char(']'));
    assert_eq!(a.score.graded, 0);
}

#[test]
fn help_scrolls_when_the_terminal_is_short() {
    let mut a = app("lecture-2");
    key(&mut a, KeyCode::Char('?'));
    let rows = screen(&a, 80, 24).join("\n");
    assert!(rows.contains("j/k ↑↓ scroll"), "{rows}");
    assert!(
        !rows.contains("page 2, the glossary"),
        "the last note is below"
    );
    for _ in 0..40 {
        key(&mut a, KeyCode::Char('j'));
    }
    assert_eq!(a.mode, Mode::Help);
    assert!(a.help_scroll > 0 && a.help_scroll == a.help_max.get());
    let rows = screen(&a, 80, 24).join("\n");
    assert!(rows.contains("page 2, the glossary"), "{rows}");
    assert_eq!(
        a.lesson,
        app("lecture-2").lesson,
        "j scrolled, it did not switch lessons"
    );
}

#[test]
fn j_k_scroll_a_line_pgdn_a_page_and_brackets_switch_lessons() {
    let mut a = app("lecture-2");
    stage(&mut a, 2);
    screen(&a, 80, 24);
    let page = a.page_rows.get();
    assert!(
        a.scroll_max.get() > page,
        "stage 2 is longer than two pages at 80×24"
    );
    key(&mut a, KeyCode::Char('j'));
    key(&mut a, KeyCode::Down);
    assert_eq!(a.scroll, 2);
    key(&mut a, KeyCode::Char('k'));
    assert_eq!(a.scroll, 1);
    key(&mut a, KeyCode::PageDown);
    assert_eq!(a.scroll, page, "a page keeps one line of the last in view");
    key(&mut a, KeyCode::PageUp);
    key(&mut a, KeyCode::PageUp);
    assert_eq!(a.scroll, 0);
    assert_eq!(
        a.trace.lesson, "lecture-2",
        "j/k and PgDn do not switch lessons"
    );
    key(&mut a, KeyCode::Char(']'));
    assert_eq!(a.trace.lesson, "lecture-3");
    key(&mut a, KeyCode::Char('['));
    assert_eq!(a.trace.lesson, "lecture-2");
}

#[test]
fn the_header_fits_80_columns_with_its_tags() {
    let mut a = app("lecture-2");
    key(&mut a, KeyCode::Char('p'));
    stage(&mut a, 4);
    type_text(&mut a, "18.73");
    key(&mut a, KeyCode::Enter);
    let rows = screen(&a, 80, 24);
    assert!(rows[0].trim_end().ends_with("[predict 1/1]"), "{}", rows[0]);
    assert!(
        rows[0].contains("lecture-2 · Cube hits the floor"),
        "{}",
        rows[0]
    );
    assert!(rows[0].contains('…'), "the title gives way: {}", rows[0]);
}

#[test]
fn no_key_acts_while_the_terminal_is_too_small() {
    let mut a = app("lecture-2");
    let rows = screen(&a, 50, 12).join("\n");
    assert!(rows.contains("Terminal too small"), "{rows}");
    for c in ['l', 'e', 'p', ']', 'w', '?'] {
        key(&mut a, KeyCode::Char(c));
    }
    key(&mut a, KeyCode::Enter);
    assert_eq!(
        (a.page, a.predict, a.mode.clone()),
        (0, false, Mode::Normal)
    );
    assert_eq!(a.trace.lesson, "lecture-2");
    // Large enough again: keys act.
    screen(&a, 80, 24);
    key(&mut a, KeyCode::Char('l'));
    assert_eq!(a.page, 1);
    screen(&a, 50, 12);
    key(&mut a, KeyCode::Char('q'));
    assert!(a.quit, "q still quits");
}

#[test]
fn student_lessons_come_first_then_robustness_then_scenes() {
    let (lessons, _) = tui::lessons(None::<&str>).unwrap();
    let groups: Vec<&str> = lessons.iter().map(tui::group).collect();
    let first = |g: &str| groups.iter().position(|x| *x == g).unwrap();
    let last = |g: &str| groups.iter().rposition(|x| *x == g).unwrap();
    assert!(
        last("Lessons") < first("Robustness (extreme-*)"),
        "{groups:?}"
    );
    assert!(
        last("Robustness (extreme-*)") < first("Scenes (in time)"),
        "{groups:?}"
    );
    assert!(lessons[first("Robustness (extreme-*)")]
        .id
        .starts_with("extreme-"));
    // The list shows the headings where the groups start.
    let mut a = app("lecture-2");
    key(&mut a, KeyCode::Char('z'));
    let rows = screen(&a, 100, 60);
    let at = |text: &str| row_of(&rows, text).unwrap_or_else(|| panic!("{text}: {rows:#?}"));
    let robust = at("│ Robustness (extreme-*)");
    assert!(at("third-example-floor") < robust && robust < at("extreme-mass-ratio"));
    let scenes = at("│ Scenes (in time)");
    assert!(at("extreme-inertia") < scenes && scenes < at("ball-drop"));
}

#[test]
fn the_checks_panel_says_how_many_verdicts_it_leaves_out() {
    // box-stack: more verdicts than the panel has rows at 80×24.
    let mut a = app("box-stack");
    stage(&mut a, 9);
    let rows = screen(&a, 80, 24);
    let text = rows.join("\n");
    let n = a.trace.verdicts.len();
    let shown = rows
        .iter()
        .filter(|r| r.contains("│✓") || r.contains("│✗"))
        .count();
    assert!(shown < n, "box-stack has more verdicts than rows: {text}");
    assert!(
        text.contains(&format!("+{} more (Checks stage)", n - shown)),
        "{text}"
    );
    // Every shown line ends at a word: no line of the panel ends inside one
    // of the verdicts' words.
    for v in &a.trace.verdicts {
        for word in v.label.split_whitespace().filter(|w| w.len() > 3) {
            let cut = &word[..word.len() - 1];
            for r in &rows {
                let inside = r.split('│').nth(3).unwrap_or("").trim_end();
                assert!(
                    !inside.ends_with(cut) || inside.ends_with(word),
                    "'{word}' cut: {inside}"
                );
            }
        }
    }
}

#[test]
fn without_colour_the_state_after_is_drawn_dashed() {
    let at = |color: bool, n: usize| {
        let (lessons, i) = tui::lessons(Some("lecture-2")).unwrap();
        let mut a = App::new(lessons, i, 0, Theme { color });
        stage(&mut a, n);
        key(&mut a, KeyCode::Char('z')); // the picture alone, large
        screen(&a, 100, 30)
    };
    // Stage 1 draws the state before only: the same with or without colour.
    assert_eq!(at(true, 1), at(false, 1));
    // Stage 6 draws before and after: after is dashed without colour.
    let (coloured, plain) = (at(true, 6), at(false, 6));
    assert_ne!(coloured, plain, "the after arrows differ by line style");
    let plain = plain.join("\n");
    assert!(plain.contains("v′ after (dashed)"), "{plain}");
}

/// The lecture's first and third examples are drawn with corrected geometry:
/// the picture's legend says so briefly (the overview explains it), and
/// the picture keeps most of its pane; a lesson drawn as given says nothing.
#[test]
fn the_picture_says_when_it_draws_corrected_geometry() {
    for (lesson, corrected) in [
        ("lecture-1", true),
        ("lecture-3", true),
        ("lecture-2", false),
    ] {
        let rows = screen(&app(lesson), 120, 36);
        // The picture pane's text, its wrapped lines joined.
        let top = row_of(&rows, "Scene ·").unwrap();
        let col = rows[top][..rows[top].find("┌ Scene").unwrap()]
            .chars()
            .count();
        let pane: Vec<String> = rows[top + 1..]
            .iter()
            .map(|r| r.chars().skip(col + 1).collect::<String>())
            .take_while(|r| !r.starts_with('─'))
            .map(|r| r.trim_end_matches([' ', '│']).to_string())
            .collect();
        let said = pane
            .join(" ")
            .contains("drawn with corrected geometry (see Overview)");
        assert_eq!(said, corrected, "{lesson}:\n{}", pane.join("\n"));
        if said {
            // The legend is the pane's last rows: the picture keeps the rest.
            let legend = row_of(&rows, "v before").unwrap();
            assert!(legend - top > 12, "{lesson}: picture rows {top}..{legend}");
        }
    }
}
