//! The values a plant model moves by link name ([`LinkValue`]): Rust bools and numbers as the
//! raw bits of a PDO entry, checked against the entry's width and IEC type.

use plc_rules::IecType;

/// A Rust value that [`SimBus::set_input`](crate::SimBus::set_input) writes into a PDO entry
/// and [`SimBus::input`](crate::SimBus::input) / [`SimBus::output`](crate::SimBus::output) read
/// out of one: `bool`, the integers of 8 to 64 bits, `f32` and `f64`.
///
/// The rules, so a value never changes on the way:
/// - an integer or a bool goes into an integer, bit-string or `BOOL` entry if it fits the
///   entry's bits (a negative one as its two's complement, when it fits as signed); a value
///   read out must fit the Rust type asked for (a signed entry is read sign-extended);
/// - a bool reads an entry that holds 0 or 1;
/// - `f32` goes with a `REAL` entry (32 bits) and `f64` with an `LREAL` one (64 bits), and
///   no other type with either.
///
/// ```
/// use ethercat_sim::SimBus;
/// use plc_rules::bus::{devices, BusConfig};
/// let bus = SimBus::from_description(&BusConfig {
///     devices: vec![devices::ek1100("coupler"), devices::el1004("di")],
/// })?;
/// bus.set_input("ethercat.di.input3", true)?;
/// assert_eq!(bus.input::<bool>("ethercat.di.input3")?, true);
/// assert!(bus.set_input("ethercat.di.input3", 2u8).is_err(), "2 does not fit 1 bit");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait LinkValue: Copy + std::fmt::Debug + sealed::Sealed {}

/// The methods stay inside the crate: callers name the trait, never call them.
pub(crate) mod sealed {
    use super::IecType;

    /// The entry a value goes into or comes out of.
    #[derive(Clone, Copy, Debug)]
    pub struct Slot {
        /// Bits of the entry (1 to 64).
        pub bits: u32,
        /// Its IEC type.
        pub iec: IecType,
    }

    impl Slot {
        /// The entry's raw bits as a number: sign-extended for a signed type.
        pub(crate) fn number(self, raw: u64) -> i128 {
            if self.iec.is_signed() && self.bits < 64 && self.bits > 0 {
                let shift = 64 - self.bits;
                i128::from(((raw << shift) as i64) >> shift)
            } else if self.iec.is_signed() {
                i128::from(raw as i64)
            } else {
                i128::from(raw)
            }
        }

        /// `value` as the entry's raw bits, if it fits them as signed or unsigned.
        pub(crate) fn raw(self, value: i128) -> Option<u64> {
            let bits = self.bits.clamp(1, 64);
            let (lo, hi) = (-(1i128 << (bits - 1)), (1i128 << bits) - 1);
            let mask = if bits == 64 {
                u64::MAX
            } else {
                (1u64 << bits) - 1
            };
            (!self.iec.is_real() && (lo..=hi).contains(&value)).then_some(value as u64 & mask)
        }
    }

    /// How a [`LinkValue`](super::LinkValue) becomes raw bits and back.
    pub trait Sealed: Sized {
        /// The value as the entry's raw bits, or `None` if it does not fit the entry.
        fn encode(self, slot: Slot) -> Option<u64>;
        /// The value of the entry's raw bits, or `None` if this type cannot hold it.
        fn decode(raw: u64, slot: Slot) -> Option<Self>;
    }
}

use sealed::{Sealed, Slot};

impl LinkValue for bool {}
impl Sealed for bool {
    fn encode(self, slot: Slot) -> Option<u64> {
        slot.raw(i128::from(self))
    }
    fn decode(raw: u64, slot: Slot) -> Option<Self> {
        match (slot.iec.is_real(), slot.number(raw)) {
            (false, 0) => Some(false),
            (false, 1) => Some(true),
            _ => None,
        }
    }
}

macro_rules! integers {
    ($($t:ty),*) => {$(
        impl LinkValue for $t {}
        impl Sealed for $t {
            fn encode(self, slot: Slot) -> Option<u64> {
                slot.raw(i128::from(self))
            }
            fn decode(raw: u64, slot: Slot) -> Option<Self> {
                if slot.iec.is_real() {
                    return None;
                }
                <$t>::try_from(slot.number(raw)).ok()
            }
        }
    )*};
}
integers!(u8, u16, u32, u64, i8, i16, i32, i64);

impl LinkValue for f32 {}
impl Sealed for f32 {
    fn encode(self, slot: Slot) -> Option<u64> {
        (slot.iec == IecType::Real && slot.bits == 32).then_some(u64::from(self.to_bits()))
    }
    fn decode(raw: u64, slot: Slot) -> Option<Self> {
        (slot.iec == IecType::Real && slot.bits == 32).then_some(f32::from_bits(raw as u32))
    }
}

impl LinkValue for f64 {}
impl Sealed for f64 {
    fn encode(self, slot: Slot) -> Option<u64> {
        (slot.iec == IecType::Lreal && slot.bits == 64).then_some(self.to_bits())
    }
    fn decode(raw: u64, slot: Slot) -> Option<Self> {
        (slot.iec == IecType::Lreal && slot.bits == 64).then_some(f64::from_bits(raw))
    }
}

#[cfg(test)]
mod tests {
    use super::sealed::{Sealed, Slot};
    use plc_rules::IecType;

    fn slot(bits: u32, iec: IecType) -> Slot {
        Slot { bits, iec }
    }

    #[test]
    fn integers_fit_the_entrys_bits_as_signed_or_unsigned() {
        assert_eq!(15u8.encode(slot(4, IecType::Uint)), Some(15));
        assert_eq!(16u8.encode(slot(4, IecType::Uint)), None);
        assert_eq!((-1i32).encode(slot(32, IecType::Dint)), Some(0xFFFF_FFFF));
        assert_eq!((-9i8).encode(slot(4, IecType::Uint)), None);
        assert_eq!(u64::MAX.encode(slot(64, IecType::Ulint)), Some(u64::MAX));
        assert_eq!(
            1u8.encode(slot(32, IecType::Real)),
            None,
            "no integer into a REAL"
        );
    }

    #[test]
    fn a_signed_entry_reads_sign_extended_and_must_fit_the_type_asked_for() {
        let dint = slot(32, IecType::Dint);
        assert_eq!(i32::decode(0xFFFF_FFFE, dint), Some(-2));
        assert_eq!(u32::decode(0xFFFF_FFFE, dint), None);
        assert_eq!(
            u32::decode(0xFFFF_FFFE, slot(32, IecType::Udint)),
            Some(0xFFFF_FFFE)
        );
        assert_eq!(u8::decode(0x100, slot(16, IecType::Uint)), None);
        assert_eq!(bool::decode(1, slot(1, IecType::Bool)), Some(true));
        assert_eq!(bool::decode(2, slot(4, IecType::Uint)), None);
    }

    #[test]
    fn reals_go_with_real_entries_of_their_width_only() {
        assert_eq!(1.5f32.encode(slot(32, IecType::Real)), Some(0x3FC0_0000));
        assert_eq!(1.5f32.encode(slot(32, IecType::Dint)), None);
        assert_eq!(1.5f64.encode(slot(32, IecType::Real)), None);
        assert_eq!(f32::decode(0x3FC0_0000, slot(32, IecType::Real)), Some(1.5));
        assert_eq!(f64::decode(0, slot(64, IecType::Lreal)), Some(0.0));
    }
}
