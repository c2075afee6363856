//! TOML and serde errors retold in the words of a lesson file: which key is
//! duplicated, "a number" rather than "f64", the closest known field name.

use std::ops::Range;

use super::source::Note;

const SEE_README: &str = "see lessons/README.md for every field";

/// The note for an error of `toml::from_str` on `text`.
pub fn note(e: &toml::de::Error, text: &str) -> Note {
    let span = e.span().unwrap_or(0..0);
    let (message, help) = retell(e.message().trim(), text, span.clone());
    Note::new(message, span).help(help.unwrap_or_else(|| SEE_README.to_string()))
}

fn retell(message: &str, text: &str, span: Range<usize>) -> (String, Option<String>) {
    let quoted = text.get(span.clone()).unwrap_or("").trim();
    let is_table = text.get(..span.start).is_some_and(|t| t.ends_with('['));
    match message {
        "duplicate key" if is_table => (
            format!("table [{quoted}] is defined twice"),
            Some("write all of its keys under one header".into()),
        ),
        "duplicate key" => (
            format!("duplicate key `{quoted}`: a key appears once per table"),
            Some("delete one of the two lines".into()),
        ),
        "floating-point number overflowed" => (
            format!("the number {quoted} is too large for a 64-bit float (largest about 1.8e308)"),
            Some("write `inf` where infinity is meant (an immovable body's mass)".into()),
        ),
        "invalid type: map, expected a sequence" if quoted.starts_with('[') => {
            let name = quoted.trim_matches(|c| c == '[' || c == ']').trim();
            (
                format!("[{name}] must be an array of tables: write [[{name}]]"),
                Some(format!("each [[{name}]] header starts one more entry")),
            )
        }
        m if m.contains(" as i128, expected f64") => (
            format!("the integer {quoted} does not fit in 64 bits"),
            Some("write it as a float, e.g. 1e20".into()),
        ),
        m if m.starts_with("unknown field") || m.starts_with("unknown variant") => {
            let help = did_you_mean(m);
            (m.to_string(), help)
        }
        m => {
            let m = m.replace("expected f64", "expected a number");
            (m.replace("expected a sequence", "expected an array"), None)
        }
    }
}

/// "did you mean `restitution`?" for `unknown field `restitutoin`, expected one of …`.
pub(crate) fn did_you_mean(message: &str) -> Option<String> {
    let mut words = message.split('`').skip(1).step_by(2);
    let unknown = words.next()?;
    let (distance, best) = words
        .map(|w| (edit_distance(unknown, w), w))
        .min_by_key(|(d, _)| *d)?;
    (distance <= 1 + unknown.chars().count() / 4).then(|| format!("did you mean `{best}`?"))
}

/// Levenshtein distance, in characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let substitute = diagonal + usize::from(ca != *cb);
            diagonal = row[j + 1];
            row[j + 1] = substitute.min(row[j] + 1).min(diagonal + 1);
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_the_closest_name() {
        let m = "unknown field `restitutoin`, expected one of `name`, `restitution`, `friction`";
        assert_eq!(
            did_you_mean(m).as_deref(),
            Some("did you mean `restitution`?")
        );
        let m = "unknown variant `cone`, expected one of `sphere`, `box`";
        assert_eq!(did_you_mean(m), None);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("", "abc"), 3);
    }
}
