//! What an exchange runs over and what may go wrong, below both the exchange and a device's
//! mailbox: the [`Mailbox`] that carries frames, the bounds of one answer, and [`Failure`].

/// Most fragments of one answer. An entry or object description fits one mailbox of any
/// real device; a few fragments are allowed for devices with tiny mailboxes.
pub const MAX_FRAGMENTS: usize = 16;

/// Most bytes of one answer's data (a description is a few dozen bytes and a name).
pub const MAX_ANSWER: usize = 4096;

/// Why a description could not be used.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// Only this object or entry: the device answered with an SDO Info Error (its abort
    /// code), or its answer is unusable (a name too long). Other entries are still asked.
    Entry(String),
    /// The whole device: no answer in time, a mailbox error reply (no SDO information
    /// service), or an answer that breaks the protocol (a length beyond the mailbox, too many
    /// fragments, an answer for another object). It is not asked again.
    Device(String),
}

/// A mailbox that carries one request frame to a device and its answer frames back.
pub trait Mailbox {
    /// Bytes the device's input mailbox holds, its 6-byte header included.
    fn capacity(&self) -> usize;

    /// Sends one request frame (mailbox header included).
    fn send(&mut self, frame: &[u8]) -> impl Future<Output = Result<(), String>>;

    /// The next frame the device puts into its input mailbox (the whole buffer), or an error
    /// when none comes in time.
    fn receive(&mut self) -> impl Future<Output = Result<Vec<u8>, String>>;
}
