//! Labels in a figure never overlap each other (issue 16, item 7): for every
//! contact of every lesson, in each plane, the SVG's drawing labels (the
//! contact point's and the centres' placed first) have boxes that do not
//! intersect, and the contact point is always labelled.

use contact_lab::render::svg::render;

use crate::common;

/// `(box, text)` of each label between the drawing's start and the legend.
fn labels(svg: &str) -> Vec<([f64; 4], String)> {
    common::svg::label_boxes(common::svg::drawing(svg))
}

#[test]
fn no_two_labels_overlap_in_any_figure() {
    let mut figures = 0;
    common::each_contact_in_each_plane(|id, k, t, plane| {
        let svg = render(t, plane);
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
    });
    assert!(figures > 100, "{figures}");
}
