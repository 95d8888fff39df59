//! The background writer: saves from a copy, at most once per interval, and a last time at
//! stop, never in the cycle.

use super::{RetainError, RetainStore};
use plc_core::GlobalMemory;
use plc_core::memory::Memory;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Saves retained values on a background thread: at most once per interval, only when they
/// changed, and a last time when finished.
pub struct RetainWriter<I: Send + 'static> {
    tx: Option<mpsc::Sender<Option<I>>>,
    /// Returns the error of the last save at stop, if it failed.
    thread: Option<JoinHandle<Result<(), RetainError>>>,
    failed_saves: Arc<AtomicU64>,
    path: PathBuf,
}

impl<I: Clone + Send + 'static> RetainWriter<I> {
    /// Starts the writer for a program of type `T` (whose image type is `I`).
    pub fn spawn<T>(store: RetainStore, interval: Duration) -> RetainWriter<I>
    where
        T: GlobalMemory + Memory<Image = I> + Default,
    {
        Self::spawn_for(store, interval, T::default())
    }

    /// Starts the writer for the program whose variables `program` holds (their values do
    /// not matter: each image offered is read into a copy of it and saved from there).
    pub fn spawn_for<T>(store: RetainStore, interval: Duration, program: T) -> RetainWriter<I>
    where
        T: Memory<Image = I>,
    {
        Self::spawn_after(store, interval, program, None)
    }

    /// [`spawn_for`](Self::spawn_for), its first save only after `before` ended: the last
    /// save of the writer it replaces (an online change), which would otherwise overwrite
    /// the new declaration's values with the old one's.
    pub(crate) fn spawn_after<T>(
        store: RetainStore,
        interval: Duration,
        program: T,
        before: Option<JoinHandle<()>>,
    ) -> RetainWriter<I>
    where
        T: Memory<Image = I>,
    {
        let (tx, rx) = mpsc::channel::<Option<I>>();
        let failed_saves = Arc::new(AtomicU64::new(0));
        let failed = failed_saves.clone();
        let path = store.path().to_owned();
        let thread = std::thread::Builder::new()
            .name("plc-retain".into())
            .spawn(move || {
                // Saving (converting, writing, syncing the file) must not compete with a
                // realtime cycle, whose priority this thread would otherwise inherit.
                plc_shm::normal_priority();
                if let Some(before) = before {
                    let _ = before.join();
                }
                let mut pending: Option<I> = None;
                // None: nothing saved yet, so the first change is saved at once.
                let mut last_save: Option<Instant> = None;
                let due = |last: Option<Instant>| last.is_none_or(|t| t.elapsed() >= interval);
                // A failed save (disk full, directory gone) keeps the values pending: they are
                // tried again at the next interval, never dropped, and the failure is counted.
                let save = |image: I, pending: &mut Option<I>| {
                    let mut values = program.clone();
                    values.load_image(&image);
                    let result = store.save(&values);
                    if let Err(e) = &result {
                        failed.fetch_add(1, Ordering::Relaxed);
                        log::error!(target: "plc_io::retain", "{e}; the values are kept and saved again later");
                        pending.get_or_insert(image);
                    }
                    result
                };
                loop {
                    let wait = if pending.is_some() {
                        last_save.map_or(Duration::ZERO, |t| interval.saturating_sub(t.elapsed()))
                    } else {
                        Duration::from_secs(3600)
                    };
                    match rx.recv_timeout(wait) {
                        Ok(Some(image)) => pending = Some(image),
                        Ok(None) | Err(RecvTimeoutError::Disconnected) => {
                            return match pending.take() {
                                Some(image) => save(image, &mut pending),
                                None => Ok(()),
                            };
                        }
                        Err(RecvTimeoutError::Timeout) => {}
                    }
                    if pending.is_some() && due(last_save) {
                        if let Some(image) = pending.take() {
                            // A failure was counted and printed; the values stay pending.
                            let _ = save(image, &mut pending);
                        }
                        last_save = Some(Instant::now());
                    }
                }
            });
        let thread = match thread {
            Ok(t) => Some(t),
            Err(e) => {
                // Without the thread nothing would ever be saved: say so once, loudly.
                log::error!(target: "plc_io::retain",
                    "retain file {}: retained values will not be saved: cannot start the retain \
                     writer: {e}",
                    path.display()
                );
                failed_saves.fetch_add(1, Ordering::Relaxed);
                None
            }
        };
        RetainWriter {
            tx: Some(tx),
            thread,
            failed_saves,
            path,
        }
    }

    /// How many saves failed so far (each failure was printed, and its values kept to be
    /// saved again).
    pub fn failed_saves(&self) -> u64 {
        self.failed_saves.load(Ordering::Relaxed)
    }

    /// Hands over a copy of the image whose nonvolatile values changed (never blocks).
    pub fn offer(&self, image: I) {
        if let Some(tx) = &self.tx {
            let _ = tx.send(Some(image));
        }
    }

    /// Saves `last` (or what is pending) and stops the thread. An error if that last save
    /// failed: the file then holds the values of the last save that succeeded, and the caller
    /// must say so rather than report the values saved.
    pub fn finish(mut self, last: Option<I>) -> Result<(), RetainError> {
        if let Some(tx) = self.tx.take() {
            if let Some(image) = last {
                let _ = tx.send(Some(image));
            }
            let _ = tx.send(None);
        }
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(result)) => result,
            Some(Err(_)) => Err(RetainError::Io {
                path: self.path.clone(),
                error: std::io::Error::other("the retain writer thread panicked"),
            }),
            // The thread never started: nothing was ever saved.
            None => Err(RetainError::Io {
                path: self.path.clone(),
                error: std::io::Error::other("the retain writer never started"),
            }),
        }
    }
}

impl<I: Send + 'static> Drop for RetainWriter<I> {
    fn drop(&mut self) {
        if let Some(tx) = self.tx.take() {
            let _ = tx.send(None);
        }
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}
