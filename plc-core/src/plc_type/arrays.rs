//! Arrays of [`PlcType`]s as `PlcType`s: dimensions outermost first, elements and leaves in
//! row-major order.

use super::{ElementError, PlcType, sealed};
use crate::place::StructPlace;
use crate::{IecType, Value};
use core::mem::size_of;

impl<T: PlcType, const N: usize> sealed::Sealed for [T; N] {}
impl<T: PlcType, const N: usize> PlcType for [T; N] {
    const IEC_TYPE: IecType = T::IEC_TYPE;
    const __ZERO: Self = [T::__ZERO; N];
    const RANK: usize = T::RANK + 1;
    const DIMS: &'static [usize] = {
        // Dimensions beyond the third are cut here; the derive rejects such arrays with a
        // spanned error (the variable-editor rules: at most 3 dimensions).
        const fn dim<T: PlcType>(i: usize) -> usize {
            if i < T::DIMS.len() { T::DIMS[i] } else { 0 }
        }
        match T::RANK {
            0 => &[N],
            1 => &[N, dim::<T>(0)],
            _ => &[N, dim::<T>(0), dim::<T>(1)],
        }
    };
    const ELEMENTS: usize = N * T::ELEMENTS;
    const STRING_CAPACITY: usize = T::STRING_CAPACITY;
    const LEAVES: usize = N * T::LEAVES;
    const MEMBERS: &'static [crate::VarInfo] = T::MEMBERS;
    const ALARMS: &'static [crate::alarm::AlarmDecl] = T::ALARMS;
    const TYPE_NAME: Option<&'static str> = T::TYPE_NAME;
    const DEPTH: usize = T::DEPTH;
    type Repr = [T::Repr; N];
    #[inline(always)]
    fn to_repr(&self) -> Self::Repr {
        core::array::from_fn(|i| self[i].to_repr())
    }
    #[inline(always)]
    fn from_repr(repr: &Self::Repr) -> Self {
        core::array::from_fn(|i| T::from_repr(&repr[i]))
    }
    fn get_element(&self, element: usize) -> Option<Value> {
        let inner = T::LEAVES;
        self.get(element / inner)?.get_element(element % inner)
    }
    fn set_element(
        &mut self,
        element: usize,
        value: Value,
        ty: IecType,
    ) -> Result<(), ElementError> {
        let inner = T::LEAVES;
        let len = Self::LEAVES;
        let Some(item) = self.get_mut(element / inner) else {
            return Err(ElementError::OutOfRange { len });
        };
        item.set_element(element % inner, value, ty)
            .map_err(|e| match e {
                ElementError::OutOfRange { .. } => ElementError::OutOfRange { len },
                other => other,
            })
    }
    fn __places(leaf: usize, each: &mut dyn FnMut(StructPlace<Self>)) -> bool {
        let inner = T::LEAVES;
        if inner == 0 || leaf / inner >= N {
            return false;
        }
        let at = leaf / inner * size_of::<T>();
        T::__places(leaf % inner, &mut |place: StructPlace<T>| {
            // SAFETY: an array's items lie one after the other from its start, `size_of::<T>()`
            // apart (the layout Rust gives `[T; N]`), and item `leaf / inner` is below `N`.
            each(unsafe { place.within::<Self>(at) })
        })
    }
    #[inline(always)]
    fn __unpack_bits(&mut self) {
        // Optimised away for arrays of basic values, whose elements do nothing.
        if T::DEPTH > 0 {
            self.iter_mut().for_each(T::__unpack_bits);
        }
    }
    #[inline(always)]
    fn __pack_bits(&mut self) {
        if T::DEPTH > 0 {
            self.iter_mut().for_each(T::__pack_bits);
        }
    }
    #[inline(always)]
    fn __init(&mut self) {
        if T::DEPTH > 0 {
            self.iter_mut().for_each(T::__init);
        }
    }
}
