//! `detect` as a web page: the scene's detection in words (the text
//! output), then each pair's GJK and EPA iterations one step at a time,
//! each with the Minkowski picture at that iteration (the detect figure),
//! and the pair's result with its final picture.

use std::fmt::Write;

use super::{esc, figure, page};
use crate::format::Fmt;
use crate::render::detect::{self as show, steps};
use crate::trace::detect::DetectTrace;

/// Pairs a page walks through, and iterations of each: a page that stays
/// small for a pile of bodies (the text before them lists every pair).
pub const PAIRS: usize = 8;
pub const STOPS: usize = 40;

fn step(out: &mut String, id: &str, title: &str, lines: &[String], svg: Option<String>) {
    let _ = writeln!(
        out,
        "<section class=\"iteration\" data-step data-title=\"{t}\" id=\"{id}\" tabindex=\"-1\" aria-labelledby=\"{id}-h\">\n<h2 id=\"{id}-h\">{t}</h2>\n<ul>",
        t = esc(title)
    );
    for l in lines {
        let _ = writeln!(out, "<li>{}</li>", esc(l));
    }
    out.push_str("</ul>\n");
    if let Some(svg) = svg {
        let _ = writeln!(
            out,
            "<figure>{}<figcaption>The Minkowski difference A − B at this iteration.</figcaption></figure>",
            figure::inline(&svg, id)
        );
    }
    out.push_str("</section>\n");
}

pub fn document(t: &DetectTrace, f: &Fmt) -> String {
    let head = format!(
        "<h1>{}</h1>\n<p class=\"meta\">Lesson <code>{}</code> — detection at step {} (t = {} s), narrow phase {}</p>\n",
        esc(&t.title),
        esc(&t.lesson),
        t.step,
        f.num(t.time),
        t.narrow_phase
    );
    let mut body = String::from("<main>\n");
    step(&mut body, "overview", "The scene's detection", &[], None);
    // The whole text output, as printed (broad, mid and narrow phase).
    let text = show::text(t, f, 0);
    body = body.replace(
        "<ul>\n</ul>\n</section>\n",
        &format!("<pre class=\"text\">{}</pre>\n</section>\n", esc(&text)),
    );
    for (k, p) in t.pairs.iter().enumerate().take(PAIRS) {
        let stops = steps::stops(p);
        for (i, stop) in stops.iter().enumerate().take(STOPS) {
            let (title, lines) = steps::stop_lines(p, *stop, f);
            step(
                &mut body,
                &format!("p{k}-{i}"),
                &format!("{} ↔ {}: {title}", p.a, p.b),
                &lines,
                show::svg_at(t, k, i),
            );
        }
        step(
            &mut body,
            &format!("p{k}-result"),
            &format!("{} ↔ {}: result", p.a, p.b),
            &steps::result_lines(p, f),
            show::svg_at(t, k, usize::MAX),
        );
    }
    finish(
        body,
        t.pairs.len(),
        "detect",
        &format!("{} — detection", t.title),
        &head,
    )
}

/// Ends a detection page (this one and `detect --toi`'s): the pairs past
/// [`PAIRS`] said with the command that walks through one (`command`), then
/// the page.
pub fn finish(mut body: String, pairs: usize, command: &str, title: &str, head: &str) -> String {
    if pairs > PAIRS {
        let _ = writeln!(
            body,
            "<p>{} more pairs: the text above lists them; <code>{command} --pair A,B</code> walks through one.</p>",
            pairs - PAIRS
        );
    }
    body.push_str("</main>");
    page::page(title, page::Steps::Iterations, head, &body)
}
