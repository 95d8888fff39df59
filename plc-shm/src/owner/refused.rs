//! Why the owner refused a request it received: which value of it, why, and the code its
//! answer carries.

use crate::protocol::Code;

/// A refused request, as its writer is answered.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Refused {
    /// What the answer says: rejected, or forced.
    pub code: Code,
    /// The value of the request the reason is about.
    pub which: usize,
    /// Why, in words the tool shows.
    pub why: String,
}

impl Refused {
    /// Refused by the program's declaration, its `set`, or a limit.
    pub fn rejected(which: usize, why: String) -> Refused {
        Refused {
            code: Code::Rejected,
            which,
            why,
        }
    }

    /// A write to a value that is forced.
    pub fn forced(which: usize, why: String) -> Refused {
        Refused {
            code: Code::Forced,
            which,
            why,
        }
    }
}
