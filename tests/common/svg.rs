//! Reading an SVG figure back in tests: the drawing area, attributes, and
//! each label's box as the renderer estimates it (0.55 em a character,
//! 0.75 em above the baseline, 0.2 below; combining marks take no room).

/// The part of the page between the drawing's start and the legend.
pub fn drawing(svg: &str) -> &str {
    let start = svg.find("<g clip-path=\"url(#area)\">").expect("a drawing");
    let end = svg.find(">Legend<").unwrap_or(svg.len());
    &svg[start..end]
}

/// The value of attribute `name` in `tag`.
pub fn attr(tag: &str, name: &str) -> Option<String> {
    let at = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    Some(tag[at..].split('"').next()?.to_string())
}

/// `([x0, y0, x1, y1], text)` of each `<text>` in `drawing`.
pub fn label_boxes(drawing: &str) -> Vec<([f64; 4], String)> {
    drawing
        .split("<text ")
        .skip(1)
        .filter_map(|t| {
            let t = &format!(" {t}");
            let x: f64 = attr(t, "x")?.parse().ok()?;
            let y: f64 = attr(t, "y")?.parse().ok()?;
            let size: f64 = attr(t, "font-size")?.parse().ok()?;
            let text = t.split('>').nth(1)?.split('<').next()?.to_string();
            let chars = text
                .chars()
                .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
                .count() as f64;
            let w = 0.55 * size * chars;
            let x0 = match attr(t, "text-anchor").as_deref() {
                Some("middle") => x - w / 2.0,
                Some("end") => x - w,
                _ => x,
            };
            Some(([x0, y - 0.75 * size, x0 + w, y + 0.2 * size], text))
        })
        .collect()
}
