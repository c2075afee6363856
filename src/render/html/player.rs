//! `simulate` as a web page: a player of the recorded frames (drawn as SVG
//! from the figure model's outlines, player_frames.rs) with play, pause,
//! step, a scrub bar and a speed; the energy chart with a cursor at the
//! frame shown; the events, each a link to its frame; and the step whose
//! resolution was recorded (`--trace-step K`), its iterations one at a
//! time. Without JavaScript: the run's summary, the events and the film
//! strip with its charts (what `--format svg` draws).

use std::fmt::Write;

use serde_json::json;

use super::player_frames::{self, H, W};
use super::{esc, figure, page};
use crate::format::Fmt;
use crate::render::chart::{Chart, Mark, Series, PALETTE};
use crate::trace::resolver::ResolverTrace;
use crate::trace::run::{Frame, RunTrace};
use crate::trace::Plane;

const SCRIPT: &str = include_str!("player.js");

/// Events the list shows (the summary counts them all).
pub const EVENTS: usize = 200;

/// A run to play: its frames (each with its bodies), how they were thinned,
/// the summary's text, and the step recorded with `--trace-step`.
pub struct Player<'a> {
    pub run: &'a RunTrace,
    /// `--every`: one frame kept in this many steps.
    pub every: u64,
    /// The steps the run was asked for.
    pub steps: u64,
    pub summary: String,
    /// `(K, its resolution)` for `--trace-step K`.
    pub traced: Option<(u64, &'a ResolverTrace)>,
    pub plane: Plane,
}

/// The energy chart and where its plot's x axis lies (for the cursor).
fn energy_chart(run: &RunTrace) -> (String, crate::render::chart::XMap) {
    let series = |name: &str, i: usize, get: &dyn Fn(&Frame) -> f64| Series {
        name: name.into(),
        points: run.frames.iter().map(|f| (f.time, get(f))).collect(),
        colour: PALETTE[i],
        mark: Mark::Line,
        dashed: i == 1,
    };
    let chart = Chart {
        title: "Energy".into(),
        x_label: "t (s)".into(),
        y_label: "J".into(),
        series: vec![
            series("kinetic", 0, &|f| f.kinetic_energy),
            series("potential", 1, &|f| f.potential_energy),
            series("total", 2, &|f| f.kinetic_energy + f.potential_energy),
        ],
        ..Chart::default()
    };
    let rect = (0.0, 0.0, W, 240.0);
    let map = chart.x_map(rect);
    let mut out = format!(
        "<svg role=\"img\" class=\"figure energy\" width=\"{W}\" height=\"240\" viewBox=\"0 0 {W} 240\" aria-label=\"energy against time\"><rect width=\"100%\" height=\"100%\" fill=\"#FFFFFF\"/>"
    );
    chart.draw(&mut out, rect);
    let x = run.frames.first().map_or(map.left, |f| map.px(f.time));
    let _ = write!(
        out,
        "<line class=\"cursor\" x1=\"{x:.1}\" y1=\"{:.1}\" x2=\"{x:.1}\" y2=\"{:.1}\" stroke=\"#CC0000\" stroke-width=\"2\"/></svg>",
        map.top, map.bottom
    );
    (out, map)
}

/// The frame an event at `step` is seen on: the first at or after it.
pub fn frame_of(run: &RunTrace, step: u64) -> usize {
    run.frames
        .iter()
        .position(|f| f.step >= step)
        .unwrap_or(run.frames.len().saturating_sub(1))
}

fn controls(n: usize) -> String {
    format!(
        "<div class=\"player-controls\" role=\"toolbar\" aria-label=\"player\">\n\
         <button type=\"button\" data-do=\"back\" aria-label=\"step back\" aria-keyshortcuts=\"ArrowLeft\">◀︎ Back</button>\n\
         <button type=\"button\" data-do=\"play\" aria-label=\"play\" aria-keyshortcuts=\"Space\">▶︎ Play</button>\n\
         <button type=\"button\" data-do=\"pause\" aria-label=\"pause\" aria-keyshortcuts=\"Space\" disabled>▮▮ Pause</button>\n\
         <button type=\"button\" data-do=\"step\" aria-label=\"step\" aria-keyshortcuts=\"ArrowRight\">Step ▶︎</button>\n\
         <input type=\"range\" class=\"scrub\" min=\"0\" max=\"{}\" value=\"0\" step=\"1\" aria-label=\"frame\">\n\
         <label>Speed <select class=\"speed\" aria-label=\"speed\"><option value=\"0.1\">0.1×</option><option value=\"0.25\">0.25×</option><option value=\"0.5\">0.5×</option><option value=\"1\" selected>1×</option><option value=\"2\">2×</option><option value=\"4\">4×</option></select></label>\n\
         <output class=\"frame-counter\" aria-live=\"polite\"></output>\n</div>\n",
        n.saturating_sub(1)
    )
}

pub fn document(p: &Player, fmt: &Fmt) -> String {
    let run = p.run;
    let n = run.frames.len();
    let last = run.frames.last().map_or(0, |f| f.step);
    let thinned = if p.every > 1 {
        format!(
            "one frame in every {} steps (<code>--every {}</code>), and the last",
            p.every, p.every
        )
    } else {
        "every step (<code>--every 1</code>; <code>--every N</code> keeps one in N for a smaller page)"
            .to_string()
    };
    let mut head = format!(
        "<h1>{}</h1>\n<p class=\"meta\">Scene <code>{}</code> — dt = {} s, {} steps ({} s); the player holds {n} frames: {thinned}.</p>\n",
        esc(&run.title),
        esc(&run.lesson),
        fmt.num(run.dt),
        last,
        fmt.num(run.frames.last().map_or(0.0, |f| f.time)),
    );
    if let Some(why) = &run.stopped {
        let _ = writeln!(
            head,
            "<p class=\"warning\"><strong>Stopped:</strong> {} (asked for {} steps)</p>",
            esc(why),
            p.steps
        );
    }
    let view = player_frames::view(run, p.plane);
    let (chart, map) = energy_chart(run);
    let first = run.frames.first().map_or(String::new(), |f| {
        player_frames::moving_layer(run, f, p.plane, &view)
    });
    let mut body = String::from(
        "<main>\n<section class=\"player js-only\" id=\"player\" aria-label=\"player\">\n",
    );
    body.push_str(&controls(n));
    let _ = writeln!(
        body,
        "<svg role=\"img\" class=\"figure stage\" width=\"{W}\" height=\"{H}\" viewBox=\"0 0 {W} {H}\" aria-label=\"the scene at the frame shown\"><rect width=\"100%\" height=\"100%\" fill=\"#FFFFFF\"/><g class=\"still\">{}</g><g class=\"moving\">{first}</g></svg>",
        player_frames::still_layer(run, p.plane, &view)
    );
    let _ = writeln!(body, "<figure class=\"chart\">{chart}<figcaption>Kinetic, potential and total energy; the red line is the frame shown (click the chart to go to a time).</figcaption></figure>");
    if let Some((k, _)) = p.traced {
        let _ = writeln!(
            body,
            "<p><button type=\"button\" data-do=\"open\" data-frame=\"{}\" aria-label=\"open iterations\">Step {k}'s iterations</button> — its resolution was recorded (<code>--trace-step {k}</code>).</p>",
            frame_of(run, k)
        );
    }
    body.push_str("</section>\n");
    // Without the script: the summary and the film strip.
    let _ = writeln!(
        body,
        "<section class=\"summary\" aria-labelledby=\"summary-h\"><h2 id=\"summary-h\">Summary</h2><pre class=\"text\">{}</pre></section>",
        esc(&p.summary)
    );
    events(&mut body, p, fmt);
    if let Some((k, trace)) = p.traced {
        let _ = writeln!(
            body,
            "<details class=\"trace-step\" id=\"trace\"><summary>Step {k}'s resolution (<code>--trace-step {k}</code>): {} contacts, its iterations</summary>\n<div class=\"trace-controls js-only\"><button type=\"button\" data-it=\"prev\" aria-label=\"previous iteration\">← Previous</button> <span class=\"it-where\" aria-live=\"polite\"></span> <button type=\"button\" data-it=\"next\" aria-label=\"next iteration\">Next →</button></div>\n{}</details>",
            trace.before.len(),
            super::resolve::sections(trace, &[vec![], vec![]], fmt)
        );
    }
    let _ = writeln!(
        body,
        "<section class=\"film nojs-only\" id=\"film\" aria-labelledby=\"film-h\"><h2 id=\"film-h\">Film strip</h2><figure>{}</figure></section>",
        figure::inline(&crate::render::run::svg(run, p.plane), "film")
    );
    let data = json!({
        "every": p.every,
        "dt": run.dt,
        "frames": player_frames::frames_json(run, p.plane, &view, fmt),
        "chart": { "left": map.left, "right": map.right, "lo": map.lo, "hi": map.hi },
        "traced": p.traced.map(|(k, _)| k),
    });
    let _ = writeln!(
        body,
        "<script type=\"application/json\" id=\"frames\">{}</script>\n</main>",
        player_frames::script_safe(&data.to_string())
    );
    page::page_with(
        &format!("{} — simulation", run.title),
        page::Steps::Plain,
        &head,
        &body,
        SCRIPT,
    )
}

fn events(body: &mut String, p: &Player, fmt: &Fmt) {
    let run = p.run;
    let _ = writeln!(
        body,
        "<section class=\"events\" aria-labelledby=\"events-h\"><h2 id=\"events-h\">Events ({})</h2>",
        run.events.len()
    );
    if run.events.is_empty() && p.traced.is_none() {
        body.push_str("<p>No events.</p>\n");
    }
    body.push_str("<ol class=\"events\">\n");
    let mut traced = p.traced.map(|(k, _)| k);
    for e in run.events.iter().take(EVENTS) {
        if let Some(k) = traced.filter(|k| *k <= e.step) {
            traced_item(body, run, k);
            traced = None;
        }
        let _ = writeln!(
            body,
            "<li class=\"event {}\"><a href=\"#film\" data-frame=\"{}\">t = {} s (step {}): {}</a></li>",
            esc(e.kind),
            frame_of(run, e.step),
            fmt.num(e.time),
            e.step,
            esc(&e.text)
        );
    }
    if let Some(k) = traced {
        traced_item(body, run, k);
    }
    body.push_str("</ol>\n");
    if run.events.len() > EVENTS {
        let _ = writeln!(
            body,
            "<p>{} more events: <code>simulate --table</code> lists them all.</p>",
            run.events.len() - EVENTS
        );
    }
    body.push_str("</section>\n");
}

fn traced_item(body: &mut String, run: &RunTrace, k: u64) {
    let _ = writeln!(
        body,
        "<li class=\"event traced\"><a href=\"#trace\" data-frame=\"{}\" data-open=\"trace\">step {k}: its resolution recorded (--trace-step) — open its iterations</a></li>",
        frame_of(run, k)
    );
}
