//! [`Wording`]: what a front end chooses in a message (how names are quoted, how another place
//! is named); the words themselves are the checker's.

use std::string::String;

/// How a front end writes names and other places in messages: the words are the checker's.
pub trait Wording<L> {
    /// A name as the user's format quotes it: `` `speed` `` in Rust, `"speed"` in JSON.
    fn name(&self, name: &str) -> String;
    /// Where another declaration is, to follow its name: `" (line 12)"`, or `""` where the
    /// format has nothing better than the name.
    fn place(&self, at: &L) -> String;
    /// How to allow a misaligned address, where the format can (after "move it").
    fn allow_unaligned(&self) -> &'static str {
        ""
    }
}
