//! The one number formatter: significant digits, trailing zeros trimmed,
//! `-0` shown as `0`, scientific notation outside [1e-4, 10^digits), and a
//! value that is zero up to round-off against the scale of its quantity
//! (|x| ≤ ROUND_OFF · scale) shown as `0`.

/// Relative size under which a value is round-off of the quantity it was
/// computed from: 64 units in the last place of its scale (f64 sums of a
/// few terms of size s err by a few 1e-16 s). Kept this tight so that the
/// extreme lessons' real small values (1e-13 of a position 80 m from the
/// origin, 1e-12 of a mass ratio) still show.
pub const ROUND_OFF: f64 = 64.0 * f64::EPSILON;

/// The largest finite |x| of `xs` (0 when there is none).
pub fn scale_of<'a>(xs: impl IntoIterator<Item = &'a f64>) -> f64 {
    xs.into_iter()
        .filter(|x| x.is_finite())
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

/// `x`, or 0 when it is zero up to round-off against `scale`.
pub fn snap_zero(x: f64, scale: f64) -> f64 {
    if x.is_finite() && scale.is_finite() && x.abs() <= ROUND_OFF * scale.abs() {
        0.0
    } else {
        x
    }
}

/// The components of a vector (or the entries of a list of one quantity),
/// each snapped to 0 against the largest finite one.
pub fn snap_zeros(xs: &[f64]) -> Vec<f64> {
    let scale = scale_of(xs);
    xs.iter().map(|x| snap_zero(*x, scale)).collect()
}

/// Human number formatting (JSON carries full f64 and does not use this).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fmt {
    /// Significant digits, 1..=17.
    pub digits: usize,
}

impl Default for Fmt {
    fn default() -> Self {
        Fmt { digits: 6 }
    }
}

impl Fmt {
    pub fn new(digits: usize) -> Self {
        Fmt {
            digits: digits.clamp(1, 17),
        }
    }

    /// `(mantissa text, exponent)` when scientific, else plain text.
    fn parts(&self, x: f64) -> (String, Option<i32>) {
        if x.is_nan() {
            return ("NaN".into(), None);
        }
        if x.is_infinite() {
            return (if x > 0.0 { "inf" } else { "-inf" }.into(), None);
        }
        if x == 0.0 {
            return ("0".into(), None);
        }
        let d = self.digits;
        let sci = format!("{:.*e}", d - 1, x);
        let (mantissa, exp) = sci.split_once('e').expect("{:e} has an exponent");
        let exp: i32 = exp.parse().expect("exponent");
        if exp < -4 || exp >= d as i32 {
            (trim(mantissa), Some(exp))
        } else {
            let decimals = (d as i32 - 1 - exp).max(0) as usize;
            let s = trim(&format!("{:.*}", decimals, x));
            (if s == "-0" { "0".into() } else { s }, None)
        }
    }

    pub fn num(&self, x: f64) -> String {
        match self.parts(x) {
            (m, Some(e)) => format!("{m}e{e}"),
            (m, None) => m,
        }
    }

    pub fn num_latex(&self, x: f64) -> String {
        match self.parts(x) {
            (m, Some(e)) => format!("{m} \\times 10^{{{e}}}"),
            (m, None) if m == "inf" => "\\infty".into(),
            (m, None) if m == "-inf" => "-\\infty".into(),
            (m, None) => m,
        }
    }

    /// `x` as `num` does, but `0` when it is zero up to round-off against
    /// `scale`, the size of the quantity it belongs to (a penetration
    /// 0.0467 → -6.9e-18 is 0.0467 → 0).
    pub fn num_at(&self, x: f64, scale: f64) -> String {
        self.num(snap_zero(x, scale))
    }

    /// A change `from → to` of one quantity: both at the larger one's scale.
    pub fn change(&self, from: f64, to: f64) -> String {
        let scale = if from.is_finite() && to.is_finite() {
            from.abs().max(to.abs())
        } else {
            0.0
        };
        format!("{} → {}", self.num_at(from, scale), self.num_at(to, scale))
    }

    /// A vector's components, a component that is round-off against the
    /// largest shown as `0` (`(0.5, -6.9e-18, 0)` is `(0.5, 0, 0)`).
    pub fn list(&self, xs: &[f64]) -> String {
        snap_zeros(xs)
            .iter()
            .map(|x| self.num(*x))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// `list` in LaTeX.
    pub fn list_latex(&self, xs: &[f64]) -> String {
        snap_zeros(xs)
            .iter()
            .map(|x| self.num_latex(*x))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// `x` with exactly `decimals` decimals, as a lecture prints it
    /// (`-0` shown as `0`).
    pub fn fixed(&self, x: f64, decimals: u32) -> String {
        let s = format!("{:.*}", decimals as usize, x);
        if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
            s[1..].to_string()
        } else {
            s
        }
    }
}

/// A number as written back to the user in a message or an edit field: all
/// its digits (the shortest text that reads back as the same f64), in
/// scientific notation outside [1e-4, 1e15) so that 1e-300 is not three
/// hundred zeros. `-0` is `0`.
pub fn exact(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if !x.is_finite() || (1e-4..1e15).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

pub fn is_name(s: &str) -> bool {
    !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Placeholder names used in a template.
pub fn placeholders(template: &str) -> Vec<&str> {
    let mut names = Vec::new();
    let mut rest = template;
    while let Some(open) = rest.find('{') {
        let after = &rest[open + 1..];
        match after.find('}') {
            Some(close) if is_name(&after[..close]) => {
                names.push(&after[..close]);
                rest = &after[close + 1..];
            }
            _ => rest = after,
        }
    }
    names
}

fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::Fmt;

    #[test]
    fn round_off_against_the_scale_is_zero() {
        let f = Fmt::new(3);
        // Issue 28: `resolve box-stack --digits 3` printed 0.0467 → -6.94e-18.
        assert_eq!(f.change(0.0467, -6.938893903907228e-18), "0.0467 → 0");
        assert_eq!(f.change(-6.938893903907228e-18, 0.017), "0 → 0.017");
        assert_eq!(f.list(&[0.5, -6.9e-18, 1e-3]), "0.5, 0, 0.001");
        // Small but real, or small on its own: kept.
        assert_eq!(f.list(&[1.0, 1e-9, 0.0]), "1, 1e-9, 0");
        assert_eq!(f.list(&[80.0, 8.81e-12]), "80, 8.81e-12");
        assert_eq!(f.list(&[-6.9e-18, 0.0, 0.0]), "-6.9e-18, 0, 0");
        assert_eq!(f.num(-6.9e-18), "-6.9e-18");
        assert_eq!(f.change(f64::INFINITY, 1e-20), "inf → 1e-20");
        assert_eq!(f.list_latex(&[2.0, 1e-17]), "2, 0");
    }

    #[test]
    fn significant_digits_trimmed() {
        let f = Fmt::new(6);
        assert_eq!(f.num(18.733766), "18.7338");
        assert_eq!(f.num(2.25), "2.25");
        assert_eq!(f.num(0.0091525), "0.0091525");
        assert_eq!(f.num(240.0), "240");
        assert_eq!(f.num(-0.0), "0");
        assert_eq!(f.num(-1e-30), "-1e-30");
        assert_eq!(f.num(1.5e-7), "1.5e-7");
        assert_eq!(f.num(123456789.0), "1.23457e8");
        assert_eq!(Fmt::new(4).num(0.120104), "0.1201");
        assert_eq!(f.num(-0.0000001), "-1e-7");
    }

    #[test]
    fn rounding_to_zero_shows_zero() {
        assert_eq!(Fmt::new(3).num(-0.0004), "-0.0004");
        assert_eq!(Fmt::new(1).num(-0.04), "-0.04");
    }

    #[test]
    fn exact_numbers_round_trip_in_scientific_notation_at_the_extremes() {
        use super::exact;
        assert_eq!(exact(-0.3), "-0.3");
        assert_eq!(exact(1.0000001), "1.0000001");
        assert_eq!(exact(1e-300), "1e-300");
        assert_eq!(exact(-2.5e-170), "-2.5e-170");
        assert_eq!(exact(1e200), "1e200");
        assert_eq!(exact(123456789012.5), "123456789012.5");
        assert_eq!(exact(-0.0), "0");
        assert_eq!(exact(f64::NAN), "NaN");
        assert_eq!(exact(f64::NEG_INFINITY), "-inf");
        for x in [1e-300, 3.14159e-9, 6.02e23, -1.7976931348623157e308, 5e-324] {
            assert_eq!(exact(x).parse::<f64>().unwrap(), x);
            assert!(exact(x).len() < 30, "{}", exact(x));
        }
    }

    #[test]
    fn latex_numbers() {
        let f = Fmt::new(3);
        assert_eq!(f.num_latex(1.5e-7), "1.5 \\times 10^{-7}");
        assert_eq!(f.num_latex(f64::INFINITY), "\\infty");
    }
}
