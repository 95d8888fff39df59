//! The simulated bus behind a real network interface: an `AF_PACKET` raw socket receives the
//! MainDevice's EtherCAT frames and sends the ring's replies, so a MainDevice with its own
//! raw-socket transport (ethercrab's `tx_rx_task`) talks to the simulation over a cable or a
//! veth pair. Linux only; needs root or `CAP_NET_RAW`.
//!
//! ```no_run
//! use ethercat_sim::{Device, SimBus, raw};
//! let bus = SimBus::new(vec![Device::ek1100(), Device::el2004()]);
//! // The MainDevice runs on the other end of the veth pair `sim0`-`master0`.
//! let server = raw::spawn(raw::RawSocket::open("sim0")?, bus)?;
//! // ... run the MainDevice on "master0" ...
//! server.stop()?;
//! # Ok::<(), std::io::Error>(())
//! ```

use crate::{ETHERTYPE, SimBus};
use std::io;
use std::os::fd::{AsRawFd, FromRawFd, OwnedFd};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

/// How often a serving loop looks at its stop flag while no frame arrives.
const POLL: Duration = Duration::from_millis(20);

/// A raw socket bound to one interface that sees only EtherCAT frames.
#[derive(Debug)]
pub struct RawSocket {
    fd: OwnedFd,
}

impl RawSocket {
    /// Opens a raw socket on `interface` for ethertype 0x88A4. The socket stays in the
    /// network namespace of the calling thread, so a thread that entered a namespace can
    /// open it and hand it to another.
    pub fn open(interface: &str) -> io::Result<RawSocket> {
        let name = std::ffi::CString::new(interface)
            .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "interface name has a NUL"))?;
        // SAFETY: `name` is a valid NUL-terminated string for the duration of the call.
        let index = unsafe { libc::if_nametoindex(name.as_ptr()) };
        if index == 0 {
            return Err(io::Error::last_os_error());
        }
        let protocol = ETHERTYPE.to_be() as libc::c_int;
        // SAFETY: plain socket(2) call; the result is checked before use.
        let raw = unsafe { libc::socket(libc::AF_PACKET, libc::SOCK_RAW, protocol) };
        if raw < 0 {
            return Err(io::Error::last_os_error());
        }
        // SAFETY: `raw` is a new, valid descriptor that nothing else owns.
        let fd = unsafe { OwnedFd::from_raw_fd(raw) };
        // SAFETY: sockaddr_ll is plain data; all-zero is a valid starting value.
        let mut addr: libc::sockaddr_ll = unsafe { std::mem::zeroed() };
        addr.sll_family = libc::AF_PACKET as u16;
        addr.sll_protocol = ETHERTYPE.to_be();
        addr.sll_ifindex = index as i32;
        // SAFETY: `addr` is a valid sockaddr_ll and the length passed is its size.
        let rc = unsafe {
            libc::bind(
                fd.as_raw_fd(),
                (&addr as *const libc::sockaddr_ll).cast(),
                std::mem::size_of::<libc::sockaddr_ll>() as u32,
            )
        };
        if rc < 0 {
            return Err(io::Error::last_os_error());
        }
        let timeout = libc::timeval {
            tv_sec: 0,
            tv_usec: POLL.as_micros() as libc::suseconds_t,
        };
        // SAFETY: `timeout` is a valid timeval and the length passed is its size.
        let rc = unsafe {
            libc::setsockopt(
                fd.as_raw_fd(),
                libc::SOL_SOCKET,
                libc::SO_RCVTIMEO,
                (&timeout as *const libc::timeval).cast(),
                std::mem::size_of::<libc::timeval>() as u32,
            )
        };
        if rc < 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(RawSocket { fd })
    }

    /// Receives one frame that arrived from the wire (frames this socket sent are skipped).
    /// `Ok(None)` when nothing arrived within the poll interval.
    fn receive(&self, buf: &mut [u8]) -> io::Result<Option<usize>> {
        loop {
            // SAFETY: zeroed sockaddr_ll is valid; recvfrom writes at most `len` bytes.
            let mut from: libc::sockaddr_ll = unsafe { std::mem::zeroed() };
            let mut from_len = std::mem::size_of::<libc::sockaddr_ll>() as libc::socklen_t;
            // SAFETY: `buf` is valid for `buf.len()` bytes, `from` for `from_len` bytes.
            let n = unsafe {
                libc::recvfrom(
                    self.fd.as_raw_fd(),
                    buf.as_mut_ptr().cast(),
                    buf.len(),
                    0,
                    (&mut from as *mut libc::sockaddr_ll).cast(),
                    &mut from_len,
                )
            };
            if n < 0 {
                let e = io::Error::last_os_error();
                return match e.kind() {
                    io::ErrorKind::WouldBlock | io::ErrorKind::TimedOut => Ok(None),
                    io::ErrorKind::Interrupted => continue,
                    _ => Err(e),
                };
            }
            // Our own replies come back to a packet socket as outgoing copies.
            if from.sll_pkttype == libc::PACKET_OUTGOING {
                continue;
            }
            return Ok(Some(n as usize));
        }
    }

    fn send(&self, frame: &[u8]) -> io::Result<()> {
        // SAFETY: `frame` is valid for `frame.len()` bytes.
        let n = unsafe { libc::send(self.fd.as_raw_fd(), frame.as_ptr().cast(), frame.len(), 0) };
        if n < 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }
}

/// Answers every EtherCAT frame arriving on `socket` through `bus` until `stop` is set.
/// Malformed frames get no reply (the bus counts them).
pub fn serve(socket: &RawSocket, bus: &SimBus, stop: &AtomicBool) -> io::Result<()> {
    let mut buf = vec![0u8; 9216];
    while !stop.load(Ordering::Acquire) {
        let Some(n) = socket.receive(&mut buf)? else {
            continue;
        };
        if let Some(reply) = bus.process_frame(&buf[..n]) {
            socket.send(&reply)?;
        }
    }
    Ok(())
}

/// A thread serving the bus on a raw socket; [`stop`](Self::stop) or dropping it ends it
/// within the poll interval (20 ms).
#[derive(Debug)]
pub struct Server {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<io::Result<()>>>,
}

impl Server {
    /// Stops the thread and returns the error that ended it early, if any.
    pub fn stop(mut self) -> io::Result<()> {
        self.shutdown()
    }

    fn shutdown(&mut self) -> io::Result<()> {
        self.stop.store(true, Ordering::Release);
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(result)) => result,
            Some(Err(_)) => Err(io::Error::other("the raw socket server panicked")),
            None => Ok(()),
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.shutdown();
    }
}

/// Serves `bus` on `socket` from a thread of its own.
pub fn spawn(socket: RawSocket, bus: SimBus) -> io::Result<Server> {
    let stop = Arc::new(AtomicBool::new(false));
    let flag = stop.clone();
    let thread = std::thread::Builder::new()
        .name("ethercat-sim-raw".into())
        .spawn(move || serve(&socket, &bus, &flag))?;
    Ok(Server {
        stop,
        thread: Some(thread),
    })
}
