//! `detect --toi` as a web page: the search in words (the text output),
//! then each pair's tests one at a time — bisection's scan pieces and its
//! trials, or conservative advancement's advances — each with the step's
//! time line (the interval kept, the time tested, intersecting or apart),
//! and the pair's result with its picture (the pair at the step's start and
//! where the search found it).

use std::fmt::Write;

use super::{esc, figure};
use crate::format::Fmt;
use crate::physics::detect::ToiMethod;
use crate::render::toi as show;
use crate::trace::toi::{DetectToi, PairToi, Test};

/// Tests of each pair a page walks through (the text before them says
/// every test of every pair); pairs as the detect page
/// ([`super::detect::PAIRS`]).
pub const TESTS: usize = 60;

const W: f64 = 640.0;
const H: f64 = 136.0;
const LEFT: f64 = 20.0;
const RIGHT: f64 = W - 20.0;

/// One row of a time line at height `y`: the line from `a` to `b` (s),
/// their labels, the span `kept` shaded, the time `at` marked (✕ when the
/// pair intersects there, ○ when apart) with its label above it.
#[allow(clippy::too_many_arguments)]
fn row(
    out: &mut String,
    y: f64,
    (a, b): (f64, f64),
    kept: (f64, f64),
    at: f64,
    hit: bool,
    f: &Fmt,
) {
    let x = |t: f64| {
        let u = if b > a { (t - a) / (b - a) } else { 0.5 };
        LEFT + u.clamp(0.0, 1.0) * (RIGHT - LEFT)
    };
    let ink = if hit { "#CC0000" } else { "#0072B2" };
    let _ = write!(
        out,
        "<line x1=\"{LEFT}\" y1=\"{y}\" x2=\"{RIGHT}\" y2=\"{y}\" stroke=\"#888888\" stroke-width=\"2\"/>\
         <text x=\"{}\" y=\"{y}\" dy=\"20\" font-size=\"11\">{}</text>\
         <text x=\"{}\" y=\"{y}\" dy=\"20\" font-size=\"11\" text-anchor=\"end\">{}</text>\
         <rect class=\"kept\" x=\"{:.1}\" y=\"{}\" width=\"{:.1}\" height=\"14\" fill=\"#E69F00\" fill-opacity=\"0.45\" stroke=\"#B07800\"/>",
        LEFT,
        esc(&f.num(a)),
        RIGHT,
        esc(&f.num(b)),
        x(kept.0),
        y - 7.0,
        (x(kept.1) - x(kept.0)).max(1.5)
    );
    let px = x(at);
    if hit {
        let _ = write!(
            out,
            "<path d=\"M{:.1},{:.1} L{:.1},{:.1} M{:.1},{:.1} L{:.1},{:.1}\" stroke=\"{ink}\" stroke-width=\"2.5\"/>",
            px - 6.0, y - 6.0, px + 6.0, y + 6.0, px - 6.0, y + 6.0, px + 6.0, y - 6.0
        );
    } else {
        let _ = write!(
            out,
            "<circle cx=\"{px:.1}\" cy=\"{y}\" r=\"6\" fill=\"#FFFFFF\" stroke=\"{ink}\" stroke-width=\"2.5\"/>"
        );
    }
    let lx = px.clamp(LEFT + 40.0, RIGHT - 40.0);
    let _ = write!(
        out,
        "<text x=\"{lx:.1}\" y=\"{:.1}\" font-size=\"11\" fill=\"{ink}\" text-anchor=\"middle\">t = {} s</text>",
        y - 11.0,
        esc(&f.num(at))
    );
}

/// A test on the step's time line (0 to `dt`, the interval `[t0, t1]` the
/// test has shaded) and, below, that interval drawn at full width with
/// what the test keeps of it shaded; the time tested marked on both.
pub fn time_line(
    dt: f64,
    (t0, t1): (f64, f64),
    kept: (f64, f64),
    at: f64,
    hit: bool,
    f: &Fmt,
) -> String {
    let word = if hit { "intersecting" } else { "apart" };
    let mut out = format!(
        "<svg role=\"img\" class=\"timeline\" width=\"{W}\" height=\"{H}\" viewBox=\"0 0 {W} {H}\"><title>t = {} s: {word}; the interval [{}, {}] s of the step's [0, {}] s</title><rect width=\"100%\" height=\"100%\" fill=\"#FFFFFF\"/>",
        f.num(at),
        f.num(t0),
        f.num(t1),
        f.num(dt)
    );
    let _ = write!(
        out,
        "<text x=\"8\" y=\"14\" font-size=\"11\" fill=\"#444444\">the step (s)</text>"
    );
    row(&mut out, 38.0, (0.0, dt), (t0, t1), at, hit, f);
    let _ = write!(out, "<text x=\"8\" y=\"80\" font-size=\"11\" fill=\"#444444\">the test's interval, what it keeps shaded</text>");
    row(&mut out, 108.0, (t0, t1), kept, at, hit, f);
    out.push_str("</svg>");
    out
}

fn step(out: &mut String, id: &str, title: &str, lines: &[String], picture: &str) {
    let _ = writeln!(
        out,
        "<section class=\"iteration\" data-step data-title=\"{t}\" id=\"{id}\" tabindex=\"-1\" aria-labelledby=\"{id}-h\">\n<h2 id=\"{id}-h\">{t}</h2>\n<ul>",
        t = esc(title)
    );
    for l in lines {
        let _ = writeln!(out, "<li>{}</li>", esc(l));
    }
    if lines.is_empty() {
        out.truncate(out.len() - "<ul>\n".len());
    } else {
        out.push_str("</ul>\n");
    }
    let _ = writeln!(out, "{picture}\n</section>");
}

fn pair(out: &mut String, d: &DetectToi, k: usize, p: &PairToi, svg: Option<&str>, f: &Fmt) {
    let tests = p.record.tests();
    for (i, t) in tests.iter().enumerate().take(TESTS) {
        let (interval, kept, at, hit) = match t {
            // A scan piece is kept whole (to bisect) when it ends intersecting.
            Test::Scan { piece, .. } => {
                let kept = if piece.hit {
                    (piece.t0, piece.t1)
                } else {
                    (piece.t1, piece.t1)
                };
                ((piece.t0, piece.t1), kept, piece.t1, piece.hit)
            }
            Test::Trial(x) => {
                let kept = match p.method {
                    ToiMethod::Bisection if x.hit => (x.t0, x.trial),
                    ToiMethod::Bisection => (x.trial, x.t1),
                    ToiMethod::Conservative => (x.t1, x.t1),
                };
                ((x.t0, x.t1), kept, t.time(), x.hit)
            }
        };
        let picture = format!(
            "<figure>{}<figcaption>The step's time line: the interval the test has (shaded), then that interval at full width with what the test keeps of it; the time the test puts the pair at marked (✕ intersecting, ○ apart).</figcaption></figure>",
            time_line(d.dt, interval, kept, at, hit, f)
        );
        step(
            out,
            &format!("p{k}-{i}"),
            &format!("{} ↔ {}: test {} of {}", p.a, p.b, i + 1, tests.len()),
            &[show::test_line(p, t, f)],
            &picture,
        );
    }
    let mut lines = vec![show::outcome_line(p, f)];
    if tests.len() > TESTS {
        lines.push(format!(
            "{} more tests: the text above lists them",
            tests.len() - TESTS
        ));
    }
    let picture = svg.map_or(String::new(), |svg| {
        format!(
            "<figure>{}<figcaption>The pair at the step's start and where the search found it.</figcaption></figure>",
            figure::inline(svg, &format!("p{k}-result"))
        )
    });
    step(
        out,
        &format!("p{k}-result"),
        &format!("{} ↔ {}: result", p.a, p.b),
        &lines,
        &picture,
    );
}

/// The page; `pictures[k]`: pair k's picture (SVG), where one is drawn.
pub fn document(d: &DetectToi, pictures: &[Option<String>], f: &Fmt) -> String {
    let head = format!(
        "<h1>Time of collision: {}</h1>\n<p class=\"meta\">Step {} (t = {} s to {} s), by {}</p>\n",
        esc(&d.lesson),
        d.step,
        f.num(d.time),
        f.num(d.time + d.dt),
        esc(crate::trace::toi::method_words(d.method))
    );
    let mut body = String::from("<main>\n");
    step(
        &mut body,
        "overview",
        "The step's searches",
        &[],
        &format!("<pre class=\"text\">{}</pre>", esc(&show::text(d, f))),
    );
    for (k, p) in d.pairs.iter().enumerate().take(super::detect::PAIRS) {
        let svg = pictures.get(k).and_then(Option::as_deref);
        pair(&mut body, d, k, p, svg, f);
    }
    super::detect::finish(
        body,
        d.pairs.len(),
        "detect --toi",
        &format!("{} — time of collision", d.lesson),
        &head,
    )
}
