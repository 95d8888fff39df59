//! The simulated bus as ethercrab's network, in the same process: a thread takes the frames
//! ethercrab queues in its `PduTx`, runs them through the [`SimBus`], and hands the replies to
//! its `PduRx`. No privileges, no network interface; each MainDevice has its own `PduStorage`.

use crate::SimBus;
use ethercrab::{PduRx, PduTx};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::task::{Wake, Waker};
use std::thread::{JoinHandle, Thread};
use std::time::Duration;

/// Unparks the driver thread when ethercrab queues a frame.
struct Unpark(Thread);

impl Wake for Unpark {
    fn wake(self: Arc<Self>) {
        self.0.unpark();
    }
    fn wake_by_ref(self: &Arc<Self>) {
        self.0.unpark();
    }
}

/// The running driver; dropping it (or [`stop`](Self::stop)) ends and joins the thread.
#[derive(Debug)]
pub struct Driver {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl Driver {
    /// Stops the driver thread and waits for it.
    pub fn stop(mut self) {
        self.shutdown();
    }

    fn shutdown(&mut self) {
        self.stop.store(true, Ordering::Release);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
    }
}

impl Drop for Driver {
    fn drop(&mut self) {
        self.shutdown();
    }
}

/// Starts moving ethercrab's frames through `bus` on a thread of its own.
///
/// The replies are handed to ethercrab only after its send closure returned (EMULATOR-NOTES §1:
/// a frame is matched to its request only once it is marked sent).
pub fn spawn(
    mut tx: PduTx<'static>,
    mut rx: PduRx<'static>,
    bus: SimBus,
) -> std::io::Result<Driver> {
    let stop = Arc::new(AtomicBool::new(false));
    let stop2 = stop.clone();
    let thread = std::thread::Builder::new()
        .name("ethercat-sim".into())
        .spawn(move || {
            let waker = Waker::from(Arc::new(Unpark(std::thread::current())));
            let mut sent: Vec<Vec<u8>> = Vec::new();
            while !stop2.load(Ordering::Acquire) && !tx.should_exit() {
                // Register first, then drain: a frame queued in between still wakes us.
                tx.replace_waker(&waker);
                while let Some(frame) = tx.next_sendable_frame() {
                    let _ = frame.send_blocking(|bytes| {
                        sent.push(bytes.to_vec());
                        Ok(bytes.len())
                    });
                }
                if sent.is_empty() {
                    std::thread::park_timeout(Duration::from_millis(5));
                    continue;
                }
                for frame in sent.drain(..) {
                    if let Some(reply) = bus.process_frame(&frame) {
                        let _ = rx.receive_frame(&reply);
                    }
                }
            }
        })?;
    Ok(Driver {
        stop,
        thread: Some(thread),
    })
}
