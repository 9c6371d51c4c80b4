//! Spare f64 series for runs that repeat: a caller that runs many simulations (a timing loop,
//! a sweep, a lab recomputing on every slider move) hands each finished result back
//! ([`crate::run::SimResult::recycle`]) and the next run writes into the same memory instead
//! of asking the allocator for fresh pages (natively, a freed multi-megabyte result goes back
//! to the operating system, and the next run's first writes fault every page in again: about
//! a third of the paper case's time in a loop).

/// Spare series, each empty with its capacity kept.
#[derive(Debug, Default)]
pub struct SeriesPool {
    spare: Vec<Vec<f64>>,
}

impl SeriesPool {
    /// Most spare series kept; more handed back are freed (a run of 64 modes with 256 strain
    /// points each hands back about 1 200).
    pub const MAX_SPARE: usize = 2048;

    /// An empty pool.
    pub fn new() -> Self {
        Self::default()
    }

    /// An empty series with room for `n` values: the most recently given spare that has the
    /// room, else a new one.
    pub fn take(&mut self, n: usize) -> Vec<f64> {
        match self.spare.iter().rposition(|v| v.capacity() >= n) {
            Some(i) => self.spare.swap_remove(i),
            None => Vec::with_capacity(n),
        }
    }

    /// Keeps `v`'s memory for a later [`SeriesPool::take`] (emptied; nothing kept without
    /// capacity or beyond [`SeriesPool::MAX_SPARE`]).
    pub fn give(&mut self, mut v: Vec<f64>) {
        if v.capacity() > 0 && self.spare.len() < Self::MAX_SPARE {
            v.clear();
            self.spare.push(v);
        }
    }

    /// Number of spare series held.
    pub fn len(&self) -> usize {
        self.spare.len()
    }

    /// Whether no spare series is held.
    pub fn is_empty(&self) -> bool {
        self.spare.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::SeriesPool;

    #[test]
    fn a_given_series_comes_back_empty_with_its_memory() {
        let mut pool = SeriesPool::new();
        let v = vec![1.0; 1000];
        let ptr = v.as_ptr();
        pool.give(v);
        assert_eq!(pool.len(), 1);
        // Too small for 2000: a new one; room for 500: the spare, emptied.
        let big = pool.take(2000);
        assert!(big.capacity() >= 2000 && big.is_empty());
        assert_eq!(pool.len(), 1);
        let small = pool.take(500);
        assert_eq!(small.as_ptr(), ptr);
        assert!(small.is_empty() && small.capacity() >= 1000);
        assert!(pool.is_empty());
    }

    #[test]
    fn the_pool_keeps_at_most_max_spare_series() {
        let mut pool = SeriesPool::new();
        for _ in 0..SeriesPool::MAX_SPARE + 10 {
            pool.give(Vec::with_capacity(4));
        }
        pool.give(Vec::new());
        assert_eq!(pool.len(), SeriesPool::MAX_SPARE);
    }
}
