//! Independent pieces of a diagnosis side by side (issue 14, item 7: "a campaign … on
//! two cores"): the screening of each candidate, each candidate's second start and each
//! verification depend only on the plain fit and the candidate, never on one another, so
//! they run on worker threads while the calling thread reports progress as each ends.
//!
//! The results come back in the order of the items, whatever the number of threads and
//! whichever finished first, and each item's own computation is the same as when run
//! alone (the threads inside it, [`super::fit::parallel_map`] and
//! [`super::forward::predict`], keep their own fixed order): a diagnosis gives the same
//! numbers on one thread or many.

use super::DiagnoseError;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;

/// `each(k)` for `k` in `0..n` on up to `threads` worker threads, results in the order of
/// `k`. `done(k, finished)` is called on the calling thread as item `k` finishes (in the
/// order they finish), with the number finished so far, this one included; an error from it stops handing out items and is returned once the running
/// ones end. A panic in `each` propagates, as if it had been called in a loop.
pub fn map_reporting<T: Send>(
    n: usize,
    threads: usize,
    each: &(dyn Fn(usize) -> T + Sync),
    done: &mut dyn FnMut(usize, usize) -> Result<(), DiagnoseError>,
) -> Result<Vec<T>, DiagnoseError> {
    let mut slots: Vec<Option<T>> = (0..n).map(|_| None).collect();
    let next = AtomicUsize::new(0);
    let mut stopped: Option<DiagnoseError> = None;
    let mut finished = 0usize;
    std::thread::scope(|scope| {
        // A rendezvous channel: a worker hands its result over before it takes the next
        // item, so a stop from `done` is seen after at most one more item per worker
        // (an unbounded channel let a fast worker run ahead through every item).
        let (tx, rx) = mpsc::sync_channel::<(usize, T)>(0);
        for _ in 0..threads.clamp(1, n.max(1)) {
            let tx = tx.clone();
            let next = &next;
            scope.spawn(move || {
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    if k >= n {
                        break;
                    }
                    if tx.send((k, each(k))).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        // Ends when every worker has ended (their senders dropped).
        for (k, value) in rx {
            slots[k] = Some(value);
            finished += 1;
            if stopped.is_none()
                && let Err(e) = done(k, finished)
            {
                next.store(n, Ordering::Relaxed);
                stopped = Some(e);
            }
        }
    });
    if let Some(e) = stopped {
        return Err(e);
    }
    slots
        .into_iter()
        .collect::<Option<Vec<T>>>()
        .ok_or_else(|| DiagnoseError::Input("a worker thread ended without its result".into()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Results come in the items' order on any number of threads, every item is reported
    /// once, and an error from the progress stops the work and is returned.
    #[test]
    fn ordered_reported_and_cancellable() {
        for threads in [1, 2, 5] {
            let (mut seen, mut counts) = (Vec::new(), Vec::new());
            let out = map_reporting(7, threads, &|k| k * k, &mut |k, finished| {
                seen.push(k);
                counts.push(finished);
                Ok(())
            })
            .unwrap();
            assert_eq!(out, vec![0, 1, 4, 9, 16, 25, 36]);
            seen.sort_unstable();
            assert_eq!(seen, (0..7).collect::<Vec<_>>());
            assert_eq!(counts, (1..=7).collect::<Vec<_>>());
        }
        let ran = AtomicUsize::new(0);
        let r = map_reporting(
            100,
            1,
            &|k| {
                ran.fetch_add(1, Ordering::Relaxed);
                k
            },
            &mut |_, _| Err(DiagnoseError::Cancelled),
        );
        assert_eq!(r, Err(DiagnoseError::Cancelled));
        // One thread: the first item ran, and at most the one handed out meanwhile.
        assert!(ran.load(Ordering::Relaxed) <= 2);
        assert_eq!(
            map_reporting(0, 2, &|k| k, &mut |_, _| Ok(())).unwrap(),
            Vec::<usize>::new()
        );
    }
}
