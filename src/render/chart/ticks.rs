//! A chart axis's tick values: round ones on a linear or logarithmic
//! scale, whole numbers for a count.

use super::Scale;

/// Round tick values covering `[lo, hi]`.
pub fn ticks(lo: f64, hi: f64, scale: Scale) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi < lo {
        return vec![];
    }
    match scale {
        Scale::Log => {
            let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
            let step = ((b - a) / 6).max(1);
            (a..=b)
                .step_by(step as usize)
                .map(|e| 10f64.powi(e))
                .collect()
        }
        Scale::Linear => {
            let span = if hi > lo { hi - lo } else { lo.abs().max(1.0) };
            let raw = span / 5.0;
            let mag = 10f64.powf(raw.log10().floor());
            let step = [1.0, 2.0, 5.0, 10.0]
                .into_iter()
                .map(|m| m * mag)
                .find(|s| span / s <= 6.0)
                .unwrap_or(10.0 * mag);
            let first = (lo / step).floor() * step;
            let mut out = Vec::new();
            let mut t = first;
            while t <= hi + step * 1e-9 && out.len() < 20 {
                out.push(if t.abs() < step * 1e-9 { 0.0 } else { t });
                t += step;
            }
            if out.last().is_some_and(|&l| l < hi - step * 1e-6) {
                out.push(t);
            }
            out
        }
    }
}

/// A count's axis: from 0 (or the smallest value, if negative) to the
/// largest value, at least 1 apart, whole numbers at both ends.
pub(super) fn integer_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (0.0f64, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v.floor());
        hi = hi.max(v.ceil());
    }
    (lo, hi.max(lo + 1.0))
}

/// Whole-number ticks covering `[lo, hi]`: steps of 1, 2, 5, 10, … with at
/// most 6 of them.
pub fn integer_ticks(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi < lo {
        return vec![];
    }
    let span = (hi - lo).max(1.0);
    let mut step = 1.0;
    while span / step > 6.0 {
        let m = step / 10f64.powf(step.log10().floor());
        step *= if (1.5..=4.5).contains(&m) { 2.5 } else { 2.0 };
    }
    let first = (lo / step).floor() * step;
    let mut out = vec![];
    let mut t = first;
    while t < hi + step && out.len() < 20 {
        out.push(t);
        if t >= hi {
            break;
        }
        t += step;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_round_and_cover_the_range() {
        assert_eq!(
            ticks(0.0, 1.0, Scale::Linear),
            vec![0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0]
        );
        let t = ticks(-3.2, 17.0, Scale::Linear);
        assert!(t[0] <= -3.2 && *t.last().unwrap() >= 17.0, "{t:?}");
        assert!(t.len() <= 8);
    }

    #[test]
    fn log_ticks_are_powers_of_ten() {
        assert_eq!(
            ticks(0.003, 20.0, Scale::Log),
            vec![1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0]
        );
    }

    #[test]
    fn a_count_has_whole_number_ticks_from_zero() {
        assert_eq!(integer_range([1.0, 1.0].into_iter()), (0.0, 1.0));
        assert_eq!(integer_ticks(0.0, 1.0), vec![0.0, 1.0]);
        assert_eq!(integer_ticks(0.0, 5.0), vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);
        let t = integer_ticks(0.0, 23.0);
        assert!(t.iter().all(|x| x.fract() == 0.0) && t.len() <= 7, "{t:?}");
        assert!(*t.last().unwrap() >= 23.0, "{t:?}");
    }
}
