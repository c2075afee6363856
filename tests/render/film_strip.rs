//! `simulate SCENE --format svg`: the film strip shows the event (a body
//! below a pixel drawn at a minimum size and ringed, the tunnelling marked
//! on the frame), the awake bodies' axis counts in whole numbers, and no
//! chart's legend box is crossed by any of its curves.

use assert_cmd::Command;

use crate::common::svg::attr;

fn film(id: &str, extra: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(["simulate", id, "--format", "svg"])
        .args(extra)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// Each chart's group: from its `<g font-family=…>` line to its `</g>`.
fn charts(svg: &str) -> Vec<&str> {
    svg.split(r#"<g font-family="#)
        .skip(1)
        .map(|g| g.split("</g>").next().unwrap())
        .collect()
}

/// The page points of a path's `d` (M, L, H and V commands).
fn polyline(d: &str) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = vec![];
    for part in d.split(' ') {
        let (cmd, rest) = part.split_at(1);
        let last = out.last().copied().unwrap_or((0.0, 0.0));
        match cmd {
            "M" | "L" => {
                let (x, y) = rest.split_once(',').unwrap();
                out.push((x.parse().unwrap(), y.parse().unwrap()));
            }
            "H" => out.push((rest.parse().unwrap(), last.1)),
            "V" => out.push((last.0, rest.parse().unwrap())),
            _ => panic!("{part} in {d}"),
        }
    }
    out
}

/// Whether segment p–q meets the box (x, y, w, h) (sampled finely: the
/// boxes and segments are a few hundred pixels at most).
fn meets(p: (f64, f64), q: (f64, f64), b: (f64, f64, f64, f64)) -> bool {
    (0..=400).any(|i| {
        let t = i as f64 / 400.0;
        let (x, y) = (p.0 + (q.0 - p.0) * t, p.1 + (q.1 - p.1) * t);
        x >= b.0 && x <= b.0 + b.2 && y >= b.1 && y <= b.1 + b.3
    })
}

fn legend_clear_of_curves(svg: &str, id: &str) {
    let charts = charts(svg);
    assert_eq!(charts.len(), 3, "{id}");
    for chart in charts {
        let title = chart.split("font-weight=\"bold\">").nth(1).unwrap();
        let title = title.split('<').next().unwrap();
        let rect = chart
            .split("<rect ")
            .find(|r| r.contains(r#"class="legend-box""#))
            .unwrap_or_else(|| panic!("{id}, {title}: no legend box"));
        let num = |k: &str| {
            attr(&format!(" {rect}"), k)
                .unwrap()
                .parse::<f64>()
                .unwrap()
        };
        let b = (num("x"), num("y"), num("width"), num("height"));
        for path in chart.split("<path d=\"").skip(1) {
            let d = path.split('"').next().unwrap();
            let pts = polyline(d);
            for s in pts.windows(2) {
                assert!(
                    !meets(s[0], s[1], b),
                    "{id}, {title}: the legend box {b:?} is crossed by {:?}–{:?}",
                    s[0],
                    s[1]
                );
            }
        }
    }
}

#[test]
fn the_bullet_is_drawn_and_its_tunnelling_marked() {
    let svg = film("bullet-wall", &[]);
    let tiny: Vec<&str> = svg.split(r#"<g class="tiny">"#).skip(1).collect();
    assert!(
        tiny.iter().any(|g| g.contains(">bullet<")),
        "the bullet (2 cm across on a 50 m strip) is not drawn"
    );
    assert!(
        svg.contains("smaller than a pixel"),
        "no legend entry for the ring"
    );
    let marks: Vec<&str> = svg.split(r#"<g class="event-mark">"#).skip(1).collect();
    assert_eq!(marks.len(), 1, "one tunnelling, marked once");
    assert!(marks[0].contains("tunnelled at t = 0.0048"), "{}", marks[0]);
    // The frame it is marked on is the one ending its step (t = 1/60 s).
    assert!(
        svg.contains(">t = 0.0167 s<"),
        "the step's frame is not in the strip"
    );
    legend_clear_of_curves(&svg, "bullet-wall");
    // With continuous detection: the time of collision, marked the same way.
    let ccd = film("bullet-wall", &["--ccd", "bisection"]);
    assert!(ccd.contains("toi: collided at t = 0.0048"), "no toi mark");
}

#[test]
fn the_awake_axis_counts_in_whole_numbers() {
    let svg = film("bullet-wall", &[]);
    let awake = charts(&svg)
        .into_iter()
        .find(|c| c.contains(">Awake bodies<"))
        .unwrap();
    let ticks: Vec<String> = awake
        .split(r#"text-anchor="end">"#)
        .skip(1)
        .map(|t| t.split('<').next().unwrap().to_string())
        .collect();
    assert!(ticks.len() >= 2, "{ticks:?}");
    for t in &ticks {
        assert!(t.parse::<u32>().is_ok(), "tick {t:?} of {ticks:?}");
    }
    assert_eq!(ticks.first().map(String::as_str), Some("0"), "{ticks:?}");
}

#[test]
fn no_legend_sits_on_a_curve() {
    for id in ["stack-5", "ball-drop", "sleep-and-wake"] {
        legend_clear_of_curves(&film(id, &[]), id);
    }
}

/// The subtitle gives the time step as the scene writes it (`1/60 s`),
/// not rounded (`0.01667 s`).
#[test]
fn the_subtitle_gives_dt_as_a_fraction() {
    let svg = film("bullet-wall", &[]);
    assert!(
        svg.contains(">bullet-wall · dt = 1/60 s · 30 steps<"),
        "{}",
        &svg[..600]
    );
}
