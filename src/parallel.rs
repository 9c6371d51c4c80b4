//! Two independent pieces of work at once: on a native target the second runs on a scoped
//! thread while the first runs on the caller's; on wasm32 (one thread in the browser's worker)
//! one after the other. The results are the same either way: the pieces share nothing mutable.

/// Runs `a` and `b`, concurrently where the target has threads, and returns both results.
pub fn join<A: Send, B: Send>(
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    #[cfg(not(target_arch = "wasm32"))]
    {
        std::thread::scope(|s| {
            let hb = s.spawn(b);
            let ra = a();
            // A panic in `b` is re-raised here, as it would be without the thread.
            let rb = hb.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
            (ra, rb)
        })
    }
    #[cfg(target_arch = "wasm32")]
    {
        (a(), b())
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn both_results_come_back_in_order() {
        let (a, b) = super::join(|| (1..=10).sum::<i32>(), || "b".repeat(3));
        assert_eq!((a, b.as_str()), (55, "bbb"));
    }
}
