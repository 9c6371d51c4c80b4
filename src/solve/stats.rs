//! One pass over a series for what the run checks and reports of it: its largest magnitude and
//! its sum of squares (and from those two, whether every value is finite), accumulated in eight
//! interleaved lanes (value i goes to lane i mod 8), so the loop vectorises and the sum is not one
//! long chain of dependent additions. The lanes carry over from one slice to the next: a series fed
//! in pieces (a period at a time, while its values are still in cache) gives the same bits as
//! the whole series fed at once.

const L: usize = 8;

/// Running (max |x|, Σ x², finiteness) of a series.
#[derive(Debug, Clone, Copy, Default)]
pub struct SeriesStats {
    max: [f64; L],
    sum: [f64; L],
    len: usize,
}

impl SeriesStats {
    /// Nothing seen yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// The statistics of `x`.
    pub fn of(x: &[f64]) -> Self {
        let mut s = Self::new();
        s.push(x);
        s
    }

    fn one(&mut self, v: f64) {
        let k = self.len % L;
        // `f64::max` skips a NaN, as the lanes' comparison below does.
        self.max[k] = self.max[k].max(v.abs());
        self.sum[k] += v * v;
        self.len += 1;
    }

    /// Adds the next values of the series.
    pub fn push(&mut self, x: &[f64]) {
        let head = ((L - self.len % L) % L).min(x.len());
        for &v in &x[..head] {
            self.one(v);
        }
        let chunks = x[head..].chunks_exact(L);
        let rest = chunks.remainder();
        let full = x.len() - head - rest.len();
        for c in chunks {
            for k in 0..L {
                // `a > m` is false for a NaN: skipped (and this form vectorises).
                let a = c[k].abs();
                self.max[k] = if a > self.max[k] { a } else { self.max[k] };
                self.sum[k] += c[k] * c[k];
            }
        }
        self.len += full;
        for &v in rest {
            self.one(v);
        }
    }

    /// Largest |x_i| (NaNs skipped; 0 for an empty series).
    pub fn max_abs(&self) -> f64 {
        self.max.iter().fold(0.0_f64, |a, &b| a.max(b))
    }

    /// Σ x_i² (NaN when a value is NaN); differs from the left-to-right sum only in rounding
    /// (≤ n ε relative either way).
    pub fn sum_sq(&self) -> f64 {
        let s = &self.sum;
        ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]))
    }

    /// Whether every value seen is finite, read off the other two: an infinity is the largest
    /// magnitude from then on (the lanes' maximum skips only NaNs), and a NaN makes its lane's
    /// sum of squares NaN for good (the squares are never negative, so finite values alone can
    /// overflow a sum to +∞ but never make it NaN).
    pub fn all_finite(&self) -> bool {
        self.max_abs().is_finite() && !self.sum.iter().any(|s| s.is_nan())
    }

    /// Number of values seen.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no value was seen.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fed in pieces of any sizes, the same bits as fed whole; against plain left-to-right
    /// references to rounding; non-finite values found at any position.
    #[test]
    fn pieces_give_the_same_bits_as_the_whole() {
        let x: Vec<f64> = (0..203)
            .map(|i| ((i * 37 % 101) as f64 - 50.0) * 1.3e-3)
            .collect();
        let whole = SeriesStats::of(&x);
        for cuts in [
            vec![1],
            vec![7, 8, 9],
            vec![400],
            vec![3, 5, 11, 13, 17],
            vec![8, 16],
        ] {
            let mut s = SeriesStats::new();
            let (mut i, mut c) = (0, 0);
            while i < x.len() {
                let n = cuts[c % cuts.len()].min(x.len() - i);
                s.push(&x[i..i + n]);
                i += n;
                c += 1;
            }
            assert_eq!(s.len(), x.len());
            assert_eq!(s.max_abs().to_bits(), whole.max_abs().to_bits(), "{cuts:?}");
            assert_eq!(s.sum_sq().to_bits(), whole.sum_sq().to_bits(), "{cuts:?}");
        }
        let m = x.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let ss: f64 = x.iter().map(|v| v * v).sum();
        assert_eq!(whole.max_abs(), m);
        assert!((whole.sum_sq() - ss).abs() <= 203.0 * f64::EPSILON * ss);
        assert!(whole.all_finite());
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for i in [0, 5, 8, 100, 202] {
                let mut y = x.clone();
                y[i] = bad;
                assert!(!SeriesStats::of(&y).all_finite(), "{bad} at {i}");
                let mut s = SeriesStats::of(&y[..i]);
                s.push(&y[i..]);
                assert!(!s.all_finite(), "{bad} at {i}, in two pieces");
            }
        }
        assert!(SeriesStats::of(&[f64::MAX, -f64::MAX, -0.0]).all_finite());
        // Overflowed sums, infinities and NaNs together, from every lane, in neighbouring lanes
        // and in the same lane (`gap` values apart).
        for [first, second] in [
            [f64::MAX, f64::NAN],
            [f64::NAN, f64::MAX],
            [f64::INFINITY, f64::NAN],
            [f64::NAN, f64::NEG_INFINITY],
        ] {
            for lane in 0..L {
                for gap in [1, L] {
                    let mut y = vec![1.0; lane];
                    y.push(first);
                    y.extend(vec![1.0; gap - 1]);
                    y.push(second);
                    assert!(
                        !SeriesStats::of(&y).all_finite(),
                        "{first}, then {second} {gap} later, from lane {lane}"
                    );
                }
            }
        }
        assert_eq!(SeriesStats::new().max_abs(), 0.0);
    }
}
