//! The web pages (`--format html`, docs/html.md): for every embedded
//! lesson, no network URL in a resource attribute, every formula converted
//! (no `<merror>`), one `<section data-stage>` per stage; a worked solution
//! under 300 kB.

use crate::common;
use contact_lab::format::Fmt;
use contact_lab::render::html;

/// Every `src="…"`, `href="…"` and `url(…)` of a page that reaches the
/// network (`http:`, `https:`, or a scheme-relative `//host`).
pub fn network_urls(page: &str) -> Vec<String> {
    let lower = page.to_ascii_lowercase();
    let mut found = Vec::new();
    for opener in ["src=", "href=", "url("] {
        let mut from = 0;
        while let Some(at) = lower[from..].find(opener) {
            let start = from + at + opener.len();
            let rest = lower[start..].trim_start_matches(['"', '\'', ' ']);
            if rest.starts_with("http:") || rest.starts_with("https:") || rest.starts_with("//") {
                found.push(rest.chars().take(60).collect());
            }
            from = start;
        }
    }
    found
}

#[test]
fn the_url_finder_finds_them() {
    let page =
        "<img src=\"https://x\"><a href='http://y'>y</a><style>a{background:url( //z)}</style>\
                <svg><g clip-path=\"url(#area)\"/></svg><a href=\"#c0-impulse\">";
    assert_eq!(network_urls(page).len(), 3, "{:?}", network_urls(page));
}

fn solve_page(lesson: &contact_lab::lesson::Lesson) -> Option<String> {
    if lesson.contacts.is_empty() {
        return None;
    }
    let traces: Vec<_> = (0..lesson.contacts.len())
        .map(|k| contact_lab::worked_solution(lesson, k))
        .collect();
    Some(html::solve::document(&traces, &Fmt::new(6), None))
}

#[test]
fn no_page_reaches_the_network_and_every_formula_is_mathml() {
    let mut pages = 0;
    for lesson in common::all_lessons() {
        let Some(page) = solve_page(&lesson) else {
            continue;
        };
        pages += 1;
        assert!(
            network_urls(&page).is_empty(),
            "{}: {:?}",
            lesson.id,
            network_urls(&page)
        );
        assert!(
            !page.contains("<merror"),
            "{}: a formula not converted",
            lesson.id
        );
        assert!(
            !page.contains("<?xml"),
            "{}: an SVG declaration inline",
            lesson.id
        );
        let sections = page.matches("<section class=\"stage\" data-stage=").count();
        let stages: usize = (0..lesson.contacts.len())
            .map(|k| contact_lab::worked_solution(&lesson, k).stages.len())
            .sum();
        assert_eq!(sections, stages, "{}", lesson.id);
    }
    assert!(pages > 5, "{pages} pages");
}

#[test]
fn no_resolve_page_reaches_the_network() {
    use contact_lab::physics::resolver::Implementation;
    for lesson in common::all_lessons() {
        if lesson.contacts.is_empty() {
            continue;
        }
        let trace = contact_lab::trace::resolver::describe(
            &lesson,
            &lesson.resolver,
            Implementation::Indexed,
            true,
        );
        let page = html::resolve::document(&trace, &[vec![], vec![]], &Fmt::new(6));
        assert!(
            network_urls(&page).is_empty(),
            "{}: {:?}",
            lesson.id,
            network_urls(&page)
        );
        assert!(page.contains("data-step"), "{}", lesson.id);
    }
}

#[test]
fn a_worked_solution_page_is_under_300_kb() {
    for id in ["lecture-1", "lecture-2", "lecture-3", "friction-cube"] {
        let lesson = contact_lab::lesson::Lesson::load(id).unwrap();
        let t = contact_lab::worked_solution(&lesson, 0);
        let page = html::solve::document(&[t], &Fmt::new(6), None);
        assert!(page.len() < 300_000, "{id}: {} bytes", page.len());
        assert!(page.len() > 20_000, "{id}: {} bytes", page.len());
    }
}
