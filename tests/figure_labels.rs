//! Labels in a figure never overlap each other (issue 16, item 7): for every
//! contact of every lesson, in each plane, the SVG's drawing labels (the
//! contact point's and the centres' placed first) have boxes that do not
//! intersect, and the contact point is always labelled.

use contact_lab::lesson::Lesson;
use contact_lab::render::svg::{render, Plane};

/// `(box, text)` of each label between the drawing's start and the legend.
fn labels(svg: &str) -> Vec<([f64; 4], String)> {
    let start = svg.find("<g clip-path=\"url(#area)\">").expect("drawing");
    let end = svg.find(">Legend<").unwrap_or(svg.len());
    let attr = |tag: &str, name: &str| -> Option<String> {
        let at = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        Some(tag[at..].split('"').next()?.to_string())
    };
    svg[start..end]
        .split("<text ")
        .skip(1)
        .filter_map(|t| {
            let t = &format!(" {t}");
            let x: f64 = attr(t, "x")?.parse().ok()?;
            let y: f64 = attr(t, "y")?.parse().ok()?;
            let size: f64 = attr(t, "font-size")?.parse().ok()?;
            let anchor = attr(t, "text-anchor").unwrap_or_else(|| "start".into());
            let text = t.split('>').nth(1)?.split('<').next()?.to_string();
            let chars = text
                .chars()
                .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
                .count() as f64;
            let w = 0.55 * size * chars;
            let x0 = match anchor.as_str() {
                "middle" => x - w / 2.0,
                "end" => x - w,
                _ => x,
            };
            Some(([x0, y - 0.75 * size, x0 + w, y + 0.2 * size], text))
        })
        .collect()
}

#[test]
fn no_two_labels_overlap_in_any_figure() {
    let mut figures = 0;
    for id in contact_lab::lesson::embedded::ids() {
        let l = Lesson::load(id).unwrap();
        for k in 0..l.contacts.len() {
            let t = contact_lab::worked_solution(&l, k);
            for plane in [Plane::Xy, Plane::Yz, Plane::Zx] {
                let svg = render(&t, plane);
                let ls = labels(&svg);
                assert!(
                    ls.iter().any(|(_, s)| s == "q"),
                    "{id} #{k} {plane:?}: q is not labelled"
                );
                for (i, (a, sa)) in ls.iter().enumerate() {
                    for (b, sb) in &ls[i + 1..] {
                        let ox = a[2].min(b[2]) - a[0].max(b[0]);
                        let oy = a[3].min(b[3]) - a[1].max(b[1]);
                        assert!(
                            ox <= 2.0 || oy <= 2.0,
                            "{id} #{k} {plane:?}: «{sa}» and «{sb}» overlap"
                        );
                    }
                }
                figures += 1;
            }
        }
    }
    assert!(figures > 100, "{figures}");
}
