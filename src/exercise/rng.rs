//! SplitMix64 (Steele, Lea & Flood 2014): a tiny generator written out here
//! so the same seed gives the same exercises whatever crate versions are used.

#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n` (`n > 0`), by the multiply-shift reduction.
    pub fn below(&mut self, n: u64) -> u64 {
        ((self.next_u64() as u128 * n as u128) >> 64) as u64
    }

    pub fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.below(xs.len() as u64) as usize]
    }

    /// A number in `[lo, hi]` on a grid of `decimals` decimals.
    pub fn grid(&mut self, lo: f64, hi: f64, decimals: i32) -> f64 {
        let unit = 10f64.powi(decimals);
        let (a, b) = ((lo * unit).round() as i64, (hi * unit).round() as i64);
        let k = a + self.below((b - a + 1) as u64) as i64;
        k as f64 / unit
    }

    pub fn coin(&mut self) -> bool {
        self.next_u64() >> 63 == 1
    }

    /// The items in a seed-determined order (Fisher–Yates).
    pub fn shuffle<T>(&mut self, xs: &mut [T]) {
        for i in (1..xs.len()).rev() {
            let j = self.below(i as u64 + 1) as usize;
            xs.swap(i, j);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::SplitMix64;

    #[test]
    fn reference_values() {
        // First outputs for seed 0 in the reference implementation.
        let mut r = SplitMix64::new(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn grid_stays_in_range_on_its_grid() {
        let mut r = SplitMix64::new(7);
        for _ in 0..1000 {
            let x = r.grid(-3.0, 3.0, 2);
            assert!((-3.0..=3.0).contains(&x));
            assert!(((x * 100.0).round() - x * 100.0).abs() < 1e-9);
        }
    }
}
