//! Labels in the scene picture: an arrow's label goes past its own head, so
//! where two heads meet (two-boxes: v₁ and v₂ at the contact) each keeps
//! its label (issue 28, item 5); held as snapshots at 100×30 and 80×24.

use crate::common::tui::{app, draw, snapshot, term};

#[test]
fn two_boxes_v2_is_labelled_past_its_own_head_not_at_v1s() {
    let a = app("two-boxes", false);
    let mut t = term(100, 30);
    draw(&mut t, &a);
    let buf = t.backend().buffer().clone();
    // "v₁" and "v₂" alone (not v₁′, v₂′): the labels before the impulse,
    // as (cell column, row).
    let alone = |name: &str| {
        (0..buf.area.height)
            .find_map(|y| {
                let mut line = String::new();
                let mut cells = vec![];
                for x in 0..buf.area.width {
                    cells.push((line.len(), x));
                    line.push_str(buf[(x, y)].symbol());
                }
                let (at, _) = line
                    .match_indices(name)
                    .find(|(i, _)| !line[i + name.len()..].starts_with('′'))?;
                let x = cells.iter().rev().find(|(b, _)| *b <= at)?.1;
                Some((x, y))
            })
            .unwrap_or_else(|| panic!("no {name}"))
    };
    let (v1, v2) = (alone("v₁"), alone("v₂"));
    // v₂ = (-1, 0, 0) points left: its label left of the heads, v₁'s
    // (pointing right) right of them, on one row.
    assert_eq!(v1.1, v2.1, "v₁ at {v1:?}, v₂ at {v2:?}");
    assert!(
        v2.0 < v1.0 && v1.0 - v2.0 <= 4,
        "v₁ at {v1:?}, v₂ at {v2:?}"
    );
    snapshot("tui_two-boxes_100x30", &t);
    let mut small = term(80, 24);
    draw(&mut small, &a);
    snapshot("tui_two-boxes_80x24", &small);
}
