//! Opening the transport: ethercrab's frame storage, the driver that moves its frames (a raw
//! socket's thread, or a custom driver such as the simulated bus), and a MainDevice on them.

use super::error::EtherCatError;
use super::options::{DriverGuard, Options, Transport};
use super::{MAX_FRAMES, MAX_PDU_DATA};
use async_io::block_on;
use ethercrab::error::Error as CrabError;
use ethercrab::{MainDevice, MainDeviceConfig, PduRx, PduStorage, PduTx};

/// A MainDevice whose frames `transport` moves, and the guard that keeps the driver alive.
///
/// The frame storage is leaked (about 20 KiB per start): ethercrab needs it `'static`, and a
/// stopped bus may still see late frames.
pub(super) fn open(
    transport: Transport,
    options: &Options,
) -> Result<(MainDevice<'static>, DriverGuard), EtherCatError> {
    let storage: &'static PduStorage<MAX_FRAMES, MAX_PDU_DATA> =
        Box::leak(Box::new(PduStorage::new()));
    let (tx, rx, pdu_loop) = storage.try_split().map_err(|()| {
        EtherCatError::Transport("ethercrab's frame storage was split twice".into())
    })?;
    let driver = match transport {
        Transport::Interface(name) => spawn_interface(&name, tx, rx)?,
        Transport::Custom(start) => start(tx, rx).map_err(|e| {
            EtherCatError::Transport(format!("the EtherCAT transport did not start: {e}"))
        })?,
    };
    let maindevice = MainDevice::new(
        pdu_loop,
        options.timeouts,
        MainDeviceConfig {
            dc_static_sync_iterations: options.dc_static_sync_iterations,
            ..MainDeviceConfig::default()
        },
    );
    Ok((maindevice, driver))
}

/// ethercrab's `tx_rx_task` on a raw socket of interface `name`, on a thread of its own.
fn spawn_interface(
    name: &str,
    tx: PduTx<'static>,
    rx: PduRx<'static>,
) -> Result<DriverGuard, EtherCatError> {
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
    let handle = std::thread::Builder::new()
        .name(format!("ethercat-{name}"))
        .spawn(move || block_on(task).map(|_| ()))
        .map_err(|e| EtherCatError::Transport(format!("cannot start the EtherCAT thread: {e}")))?;
    Ok(Box::new(JoinOnDrop {
        interface: name.to_owned(),
        thread: Some(handle),
    }))
}

/// Joins the transport thread when dropped (after ethercrab told it to exit).
struct JoinOnDrop {
    interface: String,
    thread: Option<std::thread::JoinHandle<Result<(), CrabError>>>,
}

impl Drop for JoinOnDrop {
    fn drop(&mut self) {
        let Some(thread) = self.thread.take() else {
            return;
        };
        // The bus is stopped either way; what went wrong on the socket is worth a line.
        match thread.join() {
            Ok(Ok(())) => {}
            Ok(Err(e)) => log::warn!(
                "EtherCAT interface `{}`: the frame thread ended with {e}",
                self.interface
            ),
            Err(_) => log::error!(
                "EtherCAT interface `{}`: the frame thread panicked",
                self.interface
            ),
        }
    }
}
