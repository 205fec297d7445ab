//! How the springs' per-frame work is split over threads: parts claimed from the front of a
//! table's rows by every thread of a compute-pool scope, the calling thread included, until
//! none are left.

use core::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};
use std::time::{Duration, Instant};

use bevy::tasks::ComputeTaskPool;

/// The threads that run the tasks of a compute-pool scope: the pool's, and the thread that
/// opened the scope, which runs them too while it waits (1 before the pool is made). The
/// springs step inside an exclusive system, on the thread that runs the schedule (the main
/// thread), while the pool's threads have nothing else to run: on a machine with two cores,
/// where Bevy gives the pool one thread, that is both cores.
pub(crate) fn scope_threads() -> usize {
    ComputeTaskPool::try_get().map_or(1, |pool| pool.thread_num() + 1)
}

/// Rows that can be split: a table's columns, or the part of them one thread works on.
pub(crate) trait SplitRows: Send {
    /// How many rows there are.
    fn len(&self) -> usize;

    /// The first `rows` rows (at most [`len`](Self::len)), taken off the front of these.
    #[must_use]
    fn take_front(&mut self, rows: usize) -> Self;
}

/// How long the calling thread waits, awake, for the parts other threads are still working on
/// before it sleeps until they finish (as a scope's join does): long enough for a few parts,
/// short enough not to waste a time slice when the thread it waits for was preempted.
const AWAKE_WAIT: Duration = Duration::from_micros(50);

/// Runs `work` on every row of `rows`, on `threads` threads of a compute-pool scope (see
/// [`scope_threads`]): each claims a part off the front of what is left, works on it, and
/// claims the next. The results of all parts are combined by `fold`, from `identity`. Parts
/// shrink as rows run out (a share of what is left, in multiples of `grain` rows), so the
/// threads finish within a small part of each other.
///
/// The calling thread works from the start, while the pool's threads wake; when no part is
/// left it waits awake for the parts still being worked on (the scope's join would put it to
/// sleep, and waking it costs more than a part). With one thread (or no compute pool), or
/// rows for no more than one part, everything runs on the calling thread, in one part.
pub(crate) fn split_over_threads<R: SplitRows, T: Copy + Send + Sync + 'static>(
    rows: R,
    (threads, grain): (usize, usize),
    work: impl Fn(R) -> T + Sync,
    (identity, fold): (T, impl Fn(T, T) -> T + Sync),
) -> T {
    let total = rows.len();
    let pool = ComputeTaskPool::try_get().filter(|_| threads > 1 && total > grain);
    let Some(pool) = pool else {
        return fold(identity, work(rows));
    };
    let left = Mutex::new(rows);
    let done = AtomicUsize::new(0);
    // One part: `None` when no row is left.
    let claim = || {
        let mut left = left.lock().unwrap_or_else(PoisonError::into_inner);
        let rows = left.len();
        let part = (rows / (2 * threads))
            .max(1)
            .next_multiple_of(grain)
            .min(rows);
        (part > 0).then(|| left.take_front(part))
    };
    let run = || {
        let mut result = identity;
        while let Some(part) = claim() {
            result = fold(result, work_counted(part, &work, &done));
        }
        result
    };
    let run = &run;
    let mut here = identity;
    let theirs = pool.scope(|scope| {
        for _ in 1..threads {
            scope.spawn(async move { run() });
        }
        here = run();
        let since = Instant::now();
        while done.load(Ordering::Acquire) < total && since.elapsed() < AWAKE_WAIT {
            core::hint::spin_loop();
        }
    });
    theirs.into_iter().fold(here, fold)
}

/// `work` on `part`, its rows counted as done when it returns (or unwinds: a thread waiting
/// for it then stops waiting, and the scope's join passes the panic on).
fn work_counted<R: SplitRows, T>(part: R, work: impl Fn(R) -> T, done: &AtomicUsize) -> T {
    struct Counted<'a>(&'a AtomicUsize, usize);
    impl Drop for Counted<'_> {
        fn drop(&mut self) {
            self.0.fetch_add(self.1, Ordering::Release);
        }
    }
    let _counted = Counted(done, part.len());
    work(part)
}

#[cfg(test)]
mod tests {
    use bevy::tasks::{ComputeTaskPool, TaskPoolBuilder};

    use super::{SplitRows, split_over_threads};

    /// Rows that count how often they were worked on.
    struct Counts<'a>(&'a mut [u32]);

    impl SplitRows for Counts<'_> {
        fn len(&self) -> usize {
            self.0.len()
        }

        fn take_front(&mut self, rows: usize) -> Self {
            let rows = rows.min(self.0.len());
            Self(self.0.split_off_mut(..rows).unwrap_or_default())
        }
    }

    /// Every row is worked on exactly once and every part's result is folded in, whatever
    /// the number of rows (none, fewer than a part, around a part's multiples, many) and of
    /// threads (one; the pool's and this one; more than the pool has).
    #[test]
    fn every_row_is_worked_on_once() {
        ComputeTaskPool::get_or_init(|| TaskPoolBuilder::new().num_threads(2).build());
        for threads in [1, 2, 3, 8] {
            for len in [0, 1, 255, 256, 257, 1000, 4096, 100_003] {
                let mut rows = vec![0_u32; len];
                let (worked, parts) = split_over_threads(
                    Counts(&mut rows),
                    (threads, 256),
                    |part| {
                        for row in part.0.iter_mut() {
                            *row += 1;
                        }
                        (part.0.len(), 1)
                    },
                    ((0, 0), |a: (usize, usize), b: (usize, usize)| {
                        (a.0 + b.0, a.1 + b.1)
                    }),
                );
                assert_eq!(worked, len, "{threads} threads, {len} rows");
                assert!(rows.iter().all(|&count| count == 1), "{threads}, {len}");
                // Parts of at least 256 rows (but the last), at least one.
                assert!(
                    parts >= 1 && parts <= len.div_ceil(256).max(1),
                    "{parts} parts"
                );
            }
        }
    }
}
