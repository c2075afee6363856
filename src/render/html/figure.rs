//! An SVG figure put inline in a page: without its XML declaration and
//! namespace (HTML gives both), its ids made unique on the page (several
//! figures each define `area`, `hatch` and arrow heads), described for
//! screen readers by its `<title>`.

/// `svg` (a standalone SVG document) as an element of a page; `key`
/// prefixes its ids and makes them unique on that page.
pub fn inline(svg: &str, key: &str) -> String {
    let start = svg.find("<svg").unwrap_or(0);
    let body = &svg[start..];
    let body = body.replacen(" xmlns=\"http://www.w3.org/2000/svg\"", "", 1);
    let body = body.replacen("<svg ", "<svg role=\"img\" class=\"figure\" ", 1);
    let body = body
        .replace(" id=\"", &format!(" id=\"{key}-"))
        .replace("url(#", &format!("url(#{key}-"))
        .replace("href=\"#", &format!("href=\"#{key}-"));
    body.trim_end().to_string()
}

#[cfg(test)]
mod tests {
    #[test]
    fn ids_are_prefixed_and_the_declaration_dropped() {
        let svg = "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1\">\
                   <clipPath id=\"area\"/><g clip-path=\"url(#area)\"/></svg>\n";
        assert_eq!(
            super::inline(svg, "f3"),
            "<svg role=\"img\" class=\"figure\" width=\"1\"><clipPath id=\"f3-area\"/>\
             <g clip-path=\"url(#f3-area)\"/></svg>"
        );
    }
}
