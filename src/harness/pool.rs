//! Independent, deterministic jobs run a few at a time, their results back
//! in the order of the inputs: what the behaviour suite and the Fitts check
//! need (a run's result never depends on which thread ran it, so the number
//! of workers changes nothing but the wall time).

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

/// `f` of every item, on `jobs` threads (at least one, at most one per
/// item), in the order of `items`.
pub fn map_in_order<T: Sync, R: Send>(items: &[T], jobs: usize, f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let next = AtomicUsize::new(0);
    let results = Mutex::new(Vec::with_capacity(items.len()));
    std::thread::scope(|scope| {
        for _ in 0..jobs.clamp(1, items.len().max(1)) {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(item) = items.get(i) else { break };
                    let r = f(item);
                    results.lock().unwrap_or_else(PoisonError::into_inner).push((i, r));
                }
            });
        }
    });
    let mut results = results.into_inner().unwrap_or_else(PoisonError::into_inner);
    results.sort_by_key(|(i, _)| *i);
    results.into_iter().map(|(_, r)| r).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_come_back_in_input_order_whatever_the_workers() {
        let items: Vec<u64> = (0..50).collect();
        let slow_square = |x: &u64| {
            // Later items finish first on a busy worker.
            std::thread::sleep(std::time::Duration::from_micros(50 - x));
            x * x
        };
        let want: Vec<u64> = items.iter().map(|x| x * x).collect();
        for jobs in [0, 1, 3, 64] {
            assert_eq!(map_in_order(&items, jobs, slow_square), want, "{jobs} workers");
        }
        assert!(map_in_order(&[] as &[u64], 4, slow_square).is_empty());
    }
}
