//! ethercrab's group of every SubDevice, with or without distributed clocks, as one type.
//!
//! ethercrab types a group by whether SYNC0 was configured (`NoDc`, `HasDc`), and only a
//! `HasDc` group exchanges with `tx_rx_dc` (which keeps the clocks on the reference's time
//! and tells the cycle's offset to SYNC0). The backend holds either; [`Group`] forwards each
//! call to the one it holds.

use super::status::state_of;
use super::{MAX_PDI, MAX_SUBDEVICES};
use ethercrab::TxRxResponse;
use ethercrab::error::Error as CrabError;
use ethercrab::subdevice_group::{CycleInfo, HasDc, HasPdi, NoDc, Op, PreOp, SafeOp};
use ethercrab::{DefaultLock, MainDevice, SubDeviceGroup, SubDevicePdi, SubDeviceRef};
use plc_shm::BusState;

/// ethercrab's group in state `S` with distributed clocks of type `DC`.
pub(super) type Typed<S, DC> = SubDeviceGroup<MAX_SUBDEVICES, MAX_PDI, DefaultLock, S, DC>;

/// ethercrab's group of every SubDevice in state `S`: without SYNC0 (`Free`) or with it (`Dc`).
pub(super) enum Group<S> {
    /// No device was configured for SYNC0.
    Free(Typed<S, NoDc>),
    /// SYNC0 configured; exchanged with `tx_rx_dc`.
    Dc(Typed<S, HasDc>),
}

/// One exchange's answer.
pub(super) struct Exchanged {
    /// The working counter of the process data.
    pub(super) working_counter: u16,
    /// The state of the bus, from each SubDevice's.
    pub(super) state: BusState,
    /// The cycle's timing against SYNC0 (a `Dc` group only).
    pub(super) cycle: Option<CycleInfo>,
}

/// Calls `$call` on whichever group `$g` holds, wrapping a group result in the same variant.
macro_rules! each {
    ($g:expr, |$x:ident| $call:expr) => {
        match $g {
            Group::Free($x) => $call,
            Group::Dc($x) => $call,
        }
    };
    ($g:expr, |$x:ident| $call:expr => wrap) => {
        match $g {
            Group::Free($x) => $call.map(Group::Free),
            Group::Dc($x) => $call.map(Group::Dc),
        }
    };
}

impl<S: HasPdi> Group<S> {
    /// The SubDevice at ring position `index`, with its process data.
    pub(super) fn subdevice<'g>(
        &'g self,
        md: &'g MainDevice<'g>,
        index: usize,
    ) -> Result<SubDeviceRef<'g, SubDevicePdi<'g, MAX_PDI, DefaultLock>>, CrabError> {
        each!(self, |g| g.subdevice(md, index))
    }

    /// Every SubDevice, ring order.
    pub(super) fn subdevices<'g>(
        &'g self,
        md: &'g MainDevice<'g>,
    ) -> impl Iterator<Item = SubDeviceRef<'g, SubDevicePdi<'g, MAX_PDI, DefaultLock>>> {
        (0..self.len()).filter_map(move |i| self.subdevice(md, i).ok())
    }

    /// SubDevices in the group.
    pub(super) fn len(&self) -> usize {
        each!(self, |g| g.len())
    }

    /// One exchange of the process data: `tx_rx`, or `tx_rx_dc` with SYNC0 (which also
    /// distributes the reference clock's time, keeping the clocks together).
    pub(super) async fn exchange(&self, md: &MainDevice<'_>) -> Result<Exchanged, CrabError> {
        match self {
            Group::Free(g) => g.tx_rx(md).await.map(|r| answer(r, None)),
            Group::Dc(g) => {
                let r = g.tx_rx_dc(md).await?;
                let cycle = r.extra;
                Ok(answer(r, Some(cycle)))
            }
        }
    }
}

fn answer<X>(r: TxRxResponse<MAX_SUBDEVICES, X>, cycle: Option<CycleInfo>) -> Exchanged {
    Exchanged {
        working_counter: r.working_counter,
        state: state_of(&r.subdevice_states),
        cycle,
    }
}

impl Group<SafeOp> {
    /// SAFE-OP -> OP.
    pub(super) async fn into_op(self, md: &MainDevice<'_>) -> Result<Group<Op>, CrabError> {
        each!(self, |g| g.into_op(md).await => wrap)
    }

    /// SAFE-OP -> OP asked for, not waited for: the caller exchanges until every SubDevice is
    /// in OP (a DC SubDevice checks its SYNC0 and the process data on the way).
    pub(super) async fn request_into_op(self, md: &MainDevice<'_>) -> Result<Group<Op>, CrabError> {
        each!(self, |g| g.request_into_op(md).await => wrap)
    }

    /// SAFE-OP -> PRE-OP.
    pub(super) async fn into_pre_op(self, md: &MainDevice<'_>) -> Result<Group<PreOp>, CrabError> {
        each!(self, |g| g.into_pre_op(md).await => wrap)
    }
}

impl Group<Op> {
    /// OP -> SAFE-OP.
    pub(super) async fn into_safe_op(
        self,
        md: &MainDevice<'_>,
    ) -> Result<Group<SafeOp>, CrabError> {
        each!(self, |g| g.into_safe_op(md).await => wrap)
    }
}

impl Group<PreOp> {
    /// PRE-OP -> INIT.
    pub(super) async fn into_init(self, md: &MainDevice<'_>) -> Result<(), CrabError> {
        each!(self, |g| g.into_init(md).await.map(drop))
    }
}
