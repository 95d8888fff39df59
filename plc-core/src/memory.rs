//! What the runtime needs of a program's variables, whoever declared them: a
//! `#[derive(GlobalMemory)]` struct compiled into the program (every [`GlobalMemory`] is a
//! [`Memory`]), or the image of a program loaded as a module, described by its descriptor
//! (the host's own type, in `plc-module`). The first knows its variables at compile time, the
//! second only once the module is loaded: so the runtime asks an instance ([`Memory::schema`])
//! instead of the type's constants.

use crate::alarm::AlarmDecl;
use crate::place::PlacedBytes;
use crate::{BusSource, GlobalMemory, SetError, Value, VarInfo};
use zerocopy::IntoBytes;

/// A program's variables as a runtime sees them: every list is `'static` (a module's lists
/// live as long as its host, which never unloads a module).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Schema {
    /// The variables, in declaration order (see [`GlobalMemory::VARIABLES`]).
    pub variables: &'static [VarInfo],
    /// The declared alarms (see [`GlobalMemory::ALARMS`]).
    pub alarms: &'static [AlarmDecl],
    /// The layout hash of the variables.
    pub layout_hash: u64,
    /// The image's size in bytes.
    pub image_size: usize,
    /// The bus description the program was compiled against.
    pub bus: Option<BusSource>,
}

impl Schema {
    /// The schema of a compiled program.
    ///
    /// ```
    /// use plc_core::{GlobalMemory, memory::Schema};
    /// #[derive(GlobalMemory, Debug, Clone)]
    /// struct Gm { count: u16, speed: f32 }
    /// let s = Schema::of::<Gm>();
    /// assert_eq!((s.variables.len(), s.image_size, s.layout_hash), (2, 6, Gm::LAYOUT_HASH));
    /// ```
    pub const fn of<T: GlobalMemory>() -> Schema {
        Schema {
            variables: T::VARIABLES,
            alarms: T::ALARMS,
            layout_hash: T::LAYOUT_HASH,
            image_size: size_of::<T::Image>(),
            bus: T::BUS,
        }
    }
}

/// A program's variables, as the cycle, the shared memory, retained values and the I/O drive
/// them. Implemented for every [`GlobalMemory`]; a host implements it for a loaded module's
/// image.
pub trait Memory: Clone + Send + 'static {
    /// The shared-memory image: plain bytes, [`Schema::image_size`] of them.
    type Image: Clone + Send + 'static;

    /// What the variables are.
    fn schema(&self) -> Schema;

    /// An image of this program's size (its values unspecified until
    /// [`store_image`](Self::store_image)).
    fn new_image(&self) -> Self::Image;

    /// The image's bytes.
    fn image_bytes(image: &Self::Image) -> &[u8];

    /// Writes the current values into `image`.
    fn store_image(&self, image: &mut Self::Image);

    /// Takes every value from `image`.
    fn load_image(&mut self, image: &Self::Image);

    /// Copies each bit-mapped bool out of its source word (after the inputs).
    fn unpack_bits(&mut self);

    /// Copies each bit-mapped bool into its source word (before the outputs).
    fn pack_bits(&mut self);

    /// See [`GlobalMemory::try_get`].
    fn try_get(&self, index: usize, element: usize) -> Option<Value>;

    /// See [`GlobalMemory::set`].
    fn set(&mut self, index: usize, element: usize, value: Value) -> Result<(), SetError>;

    /// The stores that hold value `element` of variable `index` where it lies in `self`
    /// (see [`place::capture`](crate::place::capture)); `false` if it does not say, and a
    /// force then holds the value through [`set`](Self::set).
    fn capture_places(
        &self,
        index: usize,
        element: usize,
        each: impl FnMut(PlacedBytes<Self>),
    ) -> bool {
        let _ = (index, element, each);
        false
    }
}

impl<T: GlobalMemory + Clone + Send + 'static> Memory for T {
    type Image = T::Image;

    #[inline]
    fn schema(&self) -> Schema {
        Schema::of::<T>()
    }

    fn new_image(&self) -> T::Image {
        self.to_image()
    }

    #[inline]
    fn image_bytes(image: &T::Image) -> &[u8] {
        image.as_bytes()
    }

    #[inline]
    fn store_image(&self, image: &mut T::Image) {
        GlobalMemory::store_image(self, image)
    }

    #[inline]
    fn load_image(&mut self, image: &T::Image) {
        GlobalMemory::load_image(self, image)
    }

    #[inline]
    fn unpack_bits(&mut self) {
        GlobalMemory::unpack_bits(self)
    }

    #[inline]
    fn pack_bits(&mut self) {
        GlobalMemory::pack_bits(self)
    }

    #[inline]
    fn try_get(&self, index: usize, element: usize) -> Option<Value> {
        GlobalMemory::try_get(self, index, element)
    }

    #[inline]
    fn set(&mut self, index: usize, element: usize, value: Value) -> Result<(), SetError> {
        GlobalMemory::set(self, index, element, value)
    }

    fn capture_places(
        &self,
        index: usize,
        element: usize,
        each: impl FnMut(PlacedBytes<T>),
    ) -> bool {
        crate::place::capture(self, index, element, each)
    }
}
