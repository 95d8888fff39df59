//! Opening the transport: ethercrab's frame storage, the driver that moves its frames (a raw
//! socket's thread, or a custom driver such as the simulated bus), and a MainDevice on them.

use super::error::EtherCatError;
use super::options::{DriverGuard, Options, Transport};
use super::{MAX_FRAMES, MAX_PDU_DATA};
use async_io::block_on;
use ethercrab::{MainDevice, MainDeviceConfig, PduRx, PduStorage, PduTx};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::{Arc, OnceLock};

/// Whether the frame thread of a network interface has ended, and why: ethercrab's raw-socket
/// task returns at the first frame it cannot take (a malformed EtherCAT frame, an answer that
/// came after its request timed out), and no frame is sent or received after that. Empty for
/// a custom transport, which watches itself.
#[derive(Clone, Default)]
// The scan alone never asks why the thread ended: it reads once and stops.
#[cfg_attr(not(feature = "backend"), allow(dead_code))]
pub(super) struct FrameThread(Option<(String, Arc<OnceLock<String>>)>);

impl FrameThread {
    /// The problem to report once the thread has ended: the interface, why, and what to do.
    #[cfg(feature = "backend")]
    pub(super) fn ended(&self) -> Option<String> {
        let (interface, why) = self.0.as_ref()?;
        why.get().map(|why| {
            format!(
                "the EtherCAT frame thread of interface `{interface}` ended ({why}): no frame is \
                 sent or received any more; restart the program (ethercrab's raw-socket task \
                 stops at the first frame it cannot take, such as a late or malformed one)"
            )
        })
    }
}

/// A MainDevice whose frames `transport` moves, the guard that keeps the driver alive, and
/// what tells that an interface's frame thread ended.
///
/// The frame storage is leaked (about 20 KiB per start): ethercrab needs it `'static`, and a
/// stopped bus may still see late frames.
pub(super) fn open(
    transport: Transport,
    options: &Options,
) -> Result<(MainDevice<'static>, DriverGuard, FrameThread), EtherCatError> {
    let storage: &'static PduStorage<MAX_FRAMES, MAX_PDU_DATA> =
        Box::leak(Box::new(PduStorage::new()));
    let (tx, rx, pdu_loop) = storage.try_split().map_err(|()| {
        EtherCatError::Transport("ethercrab's frame storage was split twice".into())
    })?;
    let (driver, frame_thread) = match transport {
        Transport::Interface(name) => spawn_interface(&name, tx, rx)?,
        Transport::Custom(start) => {
            let driver = start(tx, rx).map_err(|e| {
                EtherCatError::Transport(format!("the EtherCAT transport did not start: {e}"))
            })?;
            (driver, FrameThread::default())
        }
    };
    let maindevice = MainDevice::new(
        pdu_loop,
        options.timeouts,
        MainDeviceConfig {
            dc_static_sync_iterations: options.dc_static_sync_iterations,
            ..MainDeviceConfig::default()
        },
    );
    Ok((maindevice, driver, frame_thread))
}

/// ethercrab's `tx_rx_task` on a raw socket of interface `name`, on a thread of its own.
fn spawn_interface(
    name: &str,
    tx: PduTx<'static>,
    rx: PduRx<'static>,
) -> Result<(DriverGuard, FrameThread), EtherCatError> {
    let task = ethercrab::std::tx_rx_task(name, tx, rx).map_err(|e| {
        let hint = match e.kind() {
            std::io::ErrorKind::PermissionDenied => {
                " (raw sockets need root or CAP_NET_RAW: `sudo setcap cap_net_raw=ep <program>`, \
                 or run without --interface for the simulated bus)"
            }
            std::io::ErrorKind::NotFound => " (no such interface: see `ip link`)",
            _ => "",
        };
        EtherCatError::Transport(format!("cannot open network interface `{name}`: {e}{hint}"))
    })?;
    let ended = Arc::new(OnceLock::new());
    let tells = ended.clone();
    let handle = std::thread::Builder::new()
        .name(format!("ethercat-{name}"))
        .spawn(move || {
            let outcome = match catch_unwind(AssertUnwindSafe(|| block_on(task))) {
                Ok(Ok(_)) => Ok(()),
                Ok(Err(e)) => Err(e.to_string()),
                Err(_) => Err("it panicked".to_string()),
            };
            if let Err(why) = &outcome {
                let _ = tells.set(why.clone());
            }
            outcome
        })
        .map_err(|e| EtherCatError::Transport(format!("cannot start the EtherCAT thread: {e}")))?;
    let guard = JoinOnDrop {
        interface: name.to_owned(),
        thread: Some(handle),
    };
    Ok((Box::new(guard), FrameThread(Some((name.to_owned(), ended)))))
}

/// Joins the transport thread when dropped (after ethercrab told it to exit).
struct JoinOnDrop {
    interface: String,
    thread: Option<std::thread::JoinHandle<Result<(), String>>>,
}

impl Drop for JoinOnDrop {
    fn drop(&mut self) {
        let Some(thread) = self.thread.take() else {
            return;
        };
        // The bus is stopped either way; what went wrong on the socket is worth a line.
        if let Ok(Err(why)) = thread.join() {
            log::warn!(target: "plc_io::ethercat",
                "EtherCAT interface `{}`: the frame thread ended: {why}",
                self.interface
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::fd::{AsRawFd, FromRawFd, OwnedFd};
    use std::time::{Duration, Instant};

    const ETHERCAT: u16 = 0x88A4;

    /// A raw socket on the loopback interface for EtherCAT frames, or why there is none.
    fn loopback_socket() -> Result<OwnedFd, std::io::Error> {
        // SAFETY: plain socket(2); the result is checked before use.
        let raw = unsafe {
            libc::socket(
                libc::AF_PACKET,
                libc::SOCK_RAW,
                ETHERCAT.to_be() as libc::c_int,
            )
        };
        if raw < 0 {
            return Err(std::io::Error::last_os_error());
        }
        // SAFETY: a new descriptor nothing else owns.
        let fd = unsafe { OwnedFd::from_raw_fd(raw) };
        // SAFETY: sockaddr_ll is plain data; all zero is a valid start.
        let mut addr: libc::sockaddr_ll = unsafe { std::mem::zeroed() };
        addr.sll_family = libc::AF_PACKET as u16;
        addr.sll_protocol = ETHERCAT.to_be();
        // SAFETY: a NUL-terminated name.
        addr.sll_ifindex = unsafe { libc::if_nametoindex(c"lo".as_ptr()) } as i32;
        // SAFETY: a valid sockaddr_ll and its size.
        let rc = unsafe {
            libc::bind(
                fd.as_raw_fd(),
                (&addr as *const libc::sockaddr_ll).cast(),
                size_of::<libc::sockaddr_ll>() as u32,
            )
        };
        if rc < 0 {
            return Err(std::io::Error::last_os_error());
        }
        Ok(fd)
    }

    #[test]
    fn a_frame_thread_that_a_stray_frame_ends_is_reported_as_ended_not_as_a_cable() {
        // Real ethercrab on a raw socket of `lo` (root or CAP_NET_RAW; skipped without).
        let injector = match loopback_socket() {
            Ok(fd) => fd,
            Err(e) => {
                eprintln!("skipped: no raw socket on lo ({e})");
                return;
            }
        };
        let storage: &'static PduStorage<MAX_FRAMES, MAX_PDU_DATA> =
            Box::leak(Box::new(PduStorage::new()));
        let (tx, rx, _pdu_loop) = storage.try_split().unwrap();
        let (guard, frame_thread) = spawn_interface("lo", tx, rx).unwrap();
        assert!(frame_thread.ended().is_none());
        // An EtherCAT frame from another host whose header claims more PDU bytes than it
        // carries: ethercrab's task refuses it and returns.
        let mut frame = vec![0xff; 6];
        frame.extend([0x02, 0, 0, 0, 0, 0x01]);
        frame.extend(ETHERCAT.to_be_bytes());
        frame.extend(((1u16 << 12) | 100).to_le_bytes());
        frame.extend([0u8; 4]);
        let deadline = Instant::now() + Duration::from_secs(5);
        let problem = loop {
            // SAFETY: sending a buffer we own on our socket.
            unsafe { libc::send(injector.as_raw_fd(), frame.as_ptr().cast(), frame.len(), 0) };
            if let Some(p) = frame_thread.ended() {
                break p;
            }
            assert!(
                Instant::now() < deadline,
                "the frame thread did not take the frame"
            );
            std::thread::sleep(Duration::from_millis(50));
        };
        assert!(
            problem.contains("frame thread of interface `lo` ended")
                && problem.contains("restart the program"),
            "{problem}"
        );
        drop(guard);
    }
}
