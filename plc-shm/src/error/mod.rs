//! Errors of shared memory: the one error type of the crate ([`ShmError`]), what each says
//! (its messages), and the cause an operating system's refusal keeps ([`Cause`]).

mod cause;
mod message;
mod shm_error;

pub use cause::Cause;
pub use shm_error::ShmError;
