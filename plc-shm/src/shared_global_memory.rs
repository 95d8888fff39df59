//! The two ways into a typed segment: the owner's and a reader's. Above both sides, which
//! know nothing of each other.

use crate::error::ShmError;
use crate::owner::ShmOwner;
use crate::owner::policy::Sharing;
use crate::tool::reader::ShmReader;
use plc_core::GlobalMemory;
use plc_core::memory::{Memory, Schema};
use std::marker::PhantomData;

/// A `GlobalMemory` struct in a named shared-memory segment: the two ways in.
///
/// The owner [`create`](Self::create)s it, getting a [`ShmOwner`] that
/// [`publish`](ShmOwner::publish)es every cycle; other processes [`attach`](Self::attach),
/// getting a [`ShmReader`] that takes consistent [`snapshot`](ShmReader::snapshot)s (a seqlock:
/// never a torn image), reads single variables, and sends writes over the segment's socket,
/// which the owner applies at the start of its next cycle through [`GlobalMemory::set`].
/// Owner-only calls do not exist on a reader.
///
/// The segment is sealed memory that readers map read-only; the owner's socket and lock file
/// are in its runtime directory (the crate documentation says who may connect, and how a
/// killed owner's files are taken over; the repository's README, "Security and failure
/// model", the whole model).
///
/// ```
/// use plc_core::GlobalMemory;
/// use plc_shm::SharedGlobalMemory;
///
/// #[derive(GlobalMemory, Debug, Clone)]
/// struct Gm {
///     count: u32,
///     #[plc(direction = "command")]
///     setpoint: f32,
/// }
///
/// let name = format!("doc_example_{}", std::process::id());
/// let mut owner = SharedGlobalMemory::<Gm>::create(&name)?;
/// let mut gm = Gm::default();
/// gm.count = 7;
/// owner.publish(&gm)?;
///
/// let reader = SharedGlobalMemory::<Gm>::attach(&name)?; // usually another process
/// assert_eq!(reader.snapshot()?.count, 7);
/// // A write waits for the owner's next cycle, which applies it and publishes the image that
/// // holds it: here another thread is the cycle.
/// std::thread::scope(|s| {
///     s.spawn(|| {
///         while owner.apply_requests(&mut gm) == 0 {}
///         owner.publish(&gm)
///     });
///     reader.write("setpoint", plc_core::Value::Real(2.5))
/// })?;
/// assert_eq!(gm.setpoint, 2.5);
/// # Ok::<(), plc_shm::ShmError>(())
/// ```
pub struct SharedGlobalMemory<T: GlobalMemory> {
    _never: std::convert::Infallible,
    _t: PhantomData<fn() -> T>,
}

impl<T: GlobalMemory> SharedGlobalMemory<T> {
    /// Creates segment `name` as its owner, read and written by this process's user only. A
    /// segment left by a dead owner is replaced (with a later generation); one owned by a live
    /// process is refused.
    pub fn create(name: &str) -> Result<ShmOwner<T>, ShmError>
    where
        T: Memory,
    {
        Self::create_with(name, &Sharing::new())
    }

    /// Creates segment `name` as its owner, shared with the groups `sharing` names.
    pub fn create_with(name: &str, sharing: &Sharing) -> Result<ShmOwner<T>, ShmError>
    where
        T: Memory,
    {
        ShmOwner::create(name, sharing, Schema::of::<T>())
    }

    /// Attaches to segment `name`, checking that it holds exactly `T`'s layout.
    pub fn attach(name: &str) -> Result<ShmReader<T>, ShmError> {
        ShmReader::attach(name)
    }
}
