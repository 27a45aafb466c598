//! The calling thread and one worker thread kept for a kernel's life: [`Pair::run`] runs one
//! closure here and one on the worker, and returns when both are done, like a scoped thread
//! spawned for the call, without a thread start per call.
//!
//! ```text
//!   caller   post job ─┬─ first() ─────────── wait for done ── return
//!   worker   ..idle..  └─ second() ── done ─┘ ..idle (spin, yield, then park)..
//! ```
//!
//! The handshake is two counters (`posted`, `done`): the caller stores the job and bumps
//! `posted` (release), the worker runs it and stores `done` (release), the caller waits for
//! `done` (acquire), spinning briefly, then yielding (the machine may be shared), as lumped CD's
//! pipeline waits (`kernels::lumped::pipeline`). An idle worker spins, yields for
//! [`IDLE_YIELD`], then parks until the next job unparks it. The worker starts at the first call
//! with two threads (a few allocations, once); if it cannot start, both closures run on
//! the calling thread.
//!
//! Soundness: the job borrows the caller's stack for the call only (its lifetime is erased to
//! hand it to the worker); [`Pair::run`] does not return or unwind past the job before the worker
//! has finished it (a guard waits on drop, so a panic in `first` waits too), and a panic in
//! `second` is caught on the worker and resumed on the calling thread after the wait, so a
//! panicking chunk neither hangs the run nor leaves the worker holding a borrow.

use std::any::Any;
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Spins of a wait before it yields (as `kernels::lumped::pipeline` waits).
const SPINS: u32 = 1 << 12;

/// How long an idle worker yields before it parks: long against the gap between two steps of a
/// run (its seam rows and the time loop's checks, microseconds), short against a pause of the
/// caller.
pub(crate) const IDLE_YIELD: Duration = Duration::from_millis(2);

/// A job handed to the worker: the caller's closure with its lifetime erased.
struct Job(*mut (dyn FnMut() + Send + 'static));

// SAFETY: the pointee is `Send` (a `&mut` to it may move to another thread), and the pointer is
// dereferenced only by the worker between `posted` and `done` of its call, while the caller
// does not touch the closure (`Pair::run`).
unsafe impl Send for Job {}

/// What the caller and the worker share.
#[derive(Default)]
struct Shared {
    job: Mutex<Option<Job>>,
    /// Jobs posted (written by the caller only).
    posted: AtomicUsize,
    /// Jobs finished (written by the worker only).
    done: AtomicUsize,
    /// A job's panic, resumed on the calling thread.
    panic: Mutex<Option<Box<dyn Any + Send>>>,
    stop: AtomicBool,
}

/// The worker thread and its handshake.
struct Worker {
    shared: Arc<Shared>,
    thread: JoinHandle<()>,
}

/// The calling thread and, once started, one worker thread (module docs). Cloning gives a pair
/// whose worker is not started yet; dropping it stops and joins the worker.
#[derive(Default)]
pub(crate) struct Pair {
    worker: Option<Worker>,
    /// The worker could not start: every call runs on the calling thread.
    unavailable: bool,
}

impl Clone for Pair {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl std::fmt::Debug for Pair {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Pair")
            .field("started", &self.worker.is_some())
            .finish()
    }
}

impl Drop for Pair {
    fn drop(&mut self) {
        if let Some(worker) = self.worker.take() {
            worker.shared.stop.store(true, Ordering::Release);
            worker.thread.thread().unpark();
            // The worker catches its jobs' panics; a join error has nothing left to report.
            let _ = worker.thread.join();
        }
    }
}

/// Spin, then yield, until `ready()`.
fn wait_until(mut ready: impl FnMut() -> bool) {
    let mut spins = 0u32;
    while !ready() {
        if spins < SPINS {
            spins += 1;
            std::hint::spin_loop();
        } else {
            std::thread::yield_now();
        }
    }
}

/// The worker's loop: wait for a job (spin, yield for [`IDLE_YIELD`], then park), run it with
/// its panic caught, store `done`; return when stopped.
fn serve(shared: &Shared) {
    let mut seen = 0;
    loop {
        let mut spins = 0u32;
        let mut idle_since = None;
        while shared.posted.load(Ordering::Acquire) == seen {
            if shared.stop.load(Ordering::Acquire) {
                return;
            }
            if spins < SPINS {
                spins += 1;
                std::hint::spin_loop();
            } else if idle_since.get_or_insert_with(Instant::now).elapsed() < IDLE_YIELD {
                std::thread::yield_now();
            } else {
                // A job posted since the check above has unparked this thread: `park` returns.
                std::thread::park();
            }
        }
        seen += 1;
        let job = shared
            .job
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .take();
        if let Some(Job(job)) = job {
            // SAFETY: `Pair::run` posted this pointer to its live closure and waits for `done`
            // before the closure (or anything it borrows) goes away; nothing else uses it
            // meanwhile.
            let result = catch_unwind(AssertUnwindSafe(|| unsafe { (*job)() }));
            if let Err(payload) = result {
                *shared.panic.lock().unwrap_or_else(PoisonError::into_inner) = Some(payload);
            }
        }
        shared.done.store(seen, Ordering::Release);
    }
}

/// Waits, when dropped (returning or unwinding), until the worker has finished job `ticket`
/// (or has exited, which it does only when stopped).
struct Joined<'w> {
    worker: &'w Worker,
    ticket: usize,
}

impl Drop for Joined<'_> {
    fn drop(&mut self) {
        let Worker { shared, thread } = self.worker;
        wait_until(|| shared.done.load(Ordering::Acquire) >= self.ticket || thread.is_finished());
        if std::thread::panicking() {
            // The caller's closure panicked: that panic goes on; one of the worker's too would
            // be a second, so it is dropped here rather than resumed by a later call.
            drop(
                shared
                    .panic
                    .lock()
                    .unwrap_or_else(PoisonError::into_inner)
                    .take(),
            );
        }
    }
}

impl Pair {
    /// The worker, started at the first call (`None` if it cannot start).
    fn worker(&mut self) -> Option<&Worker> {
        if self.worker.is_none() && !self.unavailable {
            let shared = Arc::new(Shared::default());
            let theirs = Arc::clone(&shared);
            match std::thread::Builder::new()
                .name("courant-chunks".into())
                .spawn(move || serve(&theirs))
            {
                Ok(thread) => self.worker = Some(Worker { shared, thread }),
                Err(_) => self.unavailable = true,
            }
        }
        self.worker.as_ref()
    }

    /// Run `first` here and `second` on the worker when `two` (else one after the other, here),
    /// returning when both are done.
    ///
    /// # Panics
    /// If `first` or `second` panics (after both are done; `second`'s panic is resumed here).
    pub(crate) fn run(&mut self, two: bool, first: impl FnOnce(), second: impl FnOnce() + Send) {
        let Some(worker) = two.then(|| self.worker()).flatten() else {
            first();
            second();
            return;
        };
        let mut second = Some(second);
        let mut call = move || {
            if let Some(second) = second.take() {
                second();
            }
        };
        let call: &mut (dyn FnMut() + Send + '_) = &mut call;
        // SAFETY: only the lifetime changes (same fat-pointer layout). The worker uses the
        // pointer until it stores `done` for this job, and `joined` (dropped before `call`, on
        // return or unwinding) waits for that, so the closure and its borrows outlive every use.
        let job: *mut (dyn FnMut() + Send + 'static) = unsafe { std::mem::transmute(call) };
        let shared = &worker.shared;
        *shared.job.lock().unwrap_or_else(PoisonError::into_inner) = Some(Job(job));
        let ticket = shared.posted.fetch_add(1, Ordering::Release) + 1;
        worker.thread.thread().unpark();
        let joined = Joined { worker, ticket };
        first();
        drop(joined);
        if shared.done.load(Ordering::Acquire) < ticket {
            panic!("the chunk worker exited before its job was done");
        }
        let panic = shared
            .panic
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .take();
        if let Some(payload) = panic {
            resume_unwind(payload);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both closures run, each exactly once, and their writes are seen after the call, on two
    /// threads (the second not on the calling thread) and on one; repeated calls reuse one
    /// worker, also after it parked.
    #[test]
    fn both_closures_run_once_and_their_writes_are_seen() {
        let mut pair = Pair::default();
        let here = std::thread::current().id();
        for call in 0..200u64 {
            let (mut a, mut b) = (0u64, None);
            pair.run(
                call % 3 != 0,
                || a += call,
                || b = Some(std::thread::current().id()),
            );
            assert_eq!(a, call);
            let on = b.expect("second ran");
            assert_eq!(on == here, call % 3 == 0, "call {call}");
            if call == 100 {
                std::thread::sleep(2 * IDLE_YIELD);
            }
        }
        assert!(pair.worker.is_some());
        let clone = pair.clone();
        assert!(clone.worker.is_none(), "a clone starts its own worker");
    }

    /// A panic in the worker's closure is resumed on the calling thread after the caller's own
    /// closure finished (no hang, no dangling borrow), and the pair works afterwards.
    #[test]
    fn a_panic_on_the_worker_is_resumed_here_and_the_pair_goes_on() {
        let mut pair = Pair::default();
        let mut first_done = false;
        let result = catch_unwind(AssertUnwindSafe(|| {
            pair.run(
                true,
                || {
                    std::thread::sleep(Duration::from_millis(20));
                    first_done = true;
                },
                || panic!("chunk 1"),
            )
        }));
        let payload = result.expect_err("the worker's panic reaches the caller");
        assert_eq!(payload.downcast_ref::<&str>(), Some(&"chunk 1"));
        assert!(first_done);
        let mut x = 0;
        pair.run(true, || (), || x = 7);
        assert_eq!(x, 7);
    }

    /// A panic in the caller's closure waits for the worker's closure to finish before it
    /// unwinds past the borrowed data (the worker's write is there after the unwind).
    #[test]
    fn a_panic_here_waits_for_the_worker() {
        let mut pair = Pair::default();
        let mut written = 0;
        let result = catch_unwind(AssertUnwindSafe(|| {
            pair.run(
                true,
                || panic!("chunk 0"),
                || {
                    std::thread::sleep(Duration::from_millis(50));
                    written = 1;
                },
            )
        }));
        assert!(result.is_err());
        assert_eq!(written, 1, "the worker finished before the caller unwound");
        let mut y = 0;
        pair.run(true, || (), || y = 3);
        assert_eq!(y, 3);
    }
}
