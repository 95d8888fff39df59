//! A typed reader of a segment: a tool with the program's Rust type, which snapshots the image
//! as that type and reads and writes its variables by name.

use super::view::View;
use crate::error::ShmError;
use crate::format::bytes;
use crate::format::descriptor::LayoutDescriptor;
use crate::format::layout::IMAGE;
use crate::format::status::{OwnerState, Status};
use plc_core::{GlobalMemory, Value};
use std::marker::PhantomData;
use std::mem::size_of;
use zerocopy::{FromZeros, IntoBytes};

/// A typed reader of a segment (an HMI, a tool with the program's type): snapshots, reads and
/// writes over the segment's socket. From
/// [`SharedGlobalMemory::attach`](crate::SharedGlobalMemory::attach).
///
/// A reader cannot publish: a second seqlock writer would let readers take torn images, so the
/// call does not exist.
///
/// ```compile_fail,E0599
/// # use plc_core::GlobalMemory;
/// # #[derive(GlobalMemory, Debug, Clone)]
/// # struct Gm { count: u32 }
/// let reader = plc_shm::SharedGlobalMemory::<Gm>::attach("press")?;
/// reader.publish(&Gm::default())?;
/// # Ok::<(), plc_shm::ShmError>(())
/// ```
pub struct ShmReader<T: GlobalMemory> {
    view: View,
    _t: PhantomData<fn() -> T>,
}

impl<T: GlobalMemory> ShmReader<T> {
    /// Whether this handle owns the segment (never).
    pub fn is_owner(&self) -> bool {
        false
    }

    /// Attaches to segment `name`, checking that it holds exactly `T`'s layout.
    pub(crate) fn attach(name: &str) -> Result<ShmReader<T>, ShmError> {
        let view = View::attach(name)?;
        if view.desc.layout_hash != T::LAYOUT_HASH || view.off.image_size != size_of::<T::Image>() {
            return Err(ShmError::LayoutMismatch {
                name: view.name().to_string(),
                expected: T::LAYOUT_HASH,
                found: view.desc.layout_hash,
            });
        }
        Ok(ShmReader {
            view,
            _t: PhantomData,
        })
    }

    /// The segment's name.
    pub fn name(&self) -> &str {
        self.view.name()
    }

    /// The generation: it grows with each new owner of this name (after a clean stop or a
    /// takeover), so a reader can tell two runs apart.
    pub fn generation(&self) -> u64 {
        self.view.generation
    }

    /// The status block.
    pub fn status(&self) -> Status {
        self.view.status()
    }

    /// The owner's state as tools show it.
    pub fn owner_state(&self) -> OwnerState {
        self.view.owner_state()
    }

    /// The layout descriptor stored in the segment.
    pub fn descriptor(&self) -> &LayoutDescriptor {
        &self.view.desc
    }

    /// A consistent copy of the variables: retries while the owner writes, never torn; an error
    /// if the owner is gone, was replaced, or stays mid-write.
    pub fn snapshot(&self) -> Result<T, ShmError> {
        let image = self.snapshot_image()?;
        Ok(T::from_image(&image))
    }

    /// A consistent copy of the image.
    pub fn snapshot_image(&self) -> Result<T::Image, ShmError> {
        let mut image = T::Image::new_zeroed();
        self.snapshot_image_into(&mut image)?;
        Ok(image)
    }

    /// A consistent copy of the image into `image`, which the caller reuses from cycle to cycle
    /// (no image-sized value is built or moved). On error `image` holds unspecified bytes.
    pub fn snapshot_image_into(&self, image: &mut T::Image) -> Result<(), ShmError> {
        let out = image.as_mut_bytes();
        self.view
            .consistent(|| bytes::load(&self.view.base, IMAGE, out))
    }

    /// One variable's value (element 0 of an array), by symbol name (case-insensitive).
    pub fn read(&self, name: &str) -> Result<Value, ShmError> {
        self.view.read_element(name, 0)
    }

    /// One element of a variable.
    pub fn read_element(&self, name: &str, element: usize) -> Result<Value, ShmError> {
        self.view.read_element(name, element)
    }

    /// Writes a variable, checked here first (unknown names, read-only, input and status
    /// variables, wrong kinds, out-of-range values, over-long strings), then applied by the
    /// owner at its next cycle: returns once applied, or with the owner's refusal.
    pub fn write(&self, name: &str, value: Value) -> Result<(), ShmError> {
        self.write_element(name, 0, value)
    }

    /// Writes one array element, as [`write`](Self::write) does.
    pub fn write_element(&self, name: &str, element: usize, value: Value) -> Result<(), ShmError> {
        self.view.write_element(name, element, value)
    }
}
