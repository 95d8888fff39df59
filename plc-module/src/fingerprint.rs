//! What a module was built with, which its host must share: the image format's version
//! (plc-core's), the compiler, the target and the panic strategy. A module built another way
//! could still load, but its image or its unwinding would not be what the host expects.

use core::fmt;

/// The build facts a module and its host compare, as the text both print.
///
/// ```
/// let host = plc_module::Fingerprint::host();
/// assert!(host.text().contains("panic=unwind"));
/// assert!(host.text().starts_with("plc-core "));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fingerprint {
    text: String,
}

impl Fingerprint {
    /// The fingerprint of a build: plc-core's version, this crate's compiler and target (the
    /// module's own when a module asks), and whether panics unwind in the crate that asks.
    pub fn of_build(panic_unwinds: bool) -> Fingerprint {
        Fingerprint {
            text: build_text(panic_unwinds),
        }
    }

    /// The host's own fingerprint.
    pub fn host() -> Fingerprint {
        Fingerprint::of_build(cfg!(panic = "unwind"))
    }

    /// A fingerprint as a module reported it.
    pub fn from_text(text: &str) -> Fingerprint {
        Fingerprint { text: text.into() }
    }

    /// The text: `plc-core 0.1.0, rustc 1.95.0 (...), x86_64-unknown-linux-gnu, panic=unwind`.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// Why a module with fingerprint `self` cannot run in a host with `host`, or `None` if it
    /// can. The answer names the part that differs first, then both whole fingerprints.
    pub fn mismatch(&self, host: &Fingerprint) -> Option<String> {
        if self == host {
            return None;
        }
        let mine: Vec<&str> = self.text.split(", ").collect();
        let theirs: Vec<&str> = host.text.split(", ").collect();
        let first = mine
            .iter()
            .zip(&theirs)
            .find(|(a, b)| a != b)
            .map(|(a, b)| format!("`{a}` where the host has `{b}`"))
            .unwrap_or_else(|| "its build differs".into());
        let fix = if self.text.ends_with("panic=abort") {
            "build it with panic = \"unwind\" (the default): a panic in a module built to \
             abort would end the running program"
        } else {
            "rebuild it with the host's compiler and plc-vars, or run the host built with the \
             module's"
        };
        Some(format!(
            "it was built with {first} (module: {}; host: {}): {fix}",
            self.text, host.text
        ))
    }
}

impl fmt::Display for Fingerprint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

fn build_text(panic_unwinds: bool) -> String {
    format!(
        "plc-core {}, {}, {}, panic={}",
        plc_core::VERSION,
        env!("PLC_MODULE_RUSTC"),
        env!("PLC_MODULE_TARGET"),
        if panic_unwinds { "unwind" } else { "abort" }
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_build_matches() {
        assert_eq!(Fingerprint::host().mismatch(&Fingerprint::host()), None);
    }

    #[test]
    fn an_aborting_module_is_refused_naming_both() {
        let module = Fingerprint::of_build(false);
        let why = module.mismatch(&Fingerprint::host()).unwrap();
        assert!(
            why.contains("`panic=abort` where the host has `panic=unwind`"),
            "{why}"
        );
        assert!(why.contains(module.text()) && why.contains(Fingerprint::host().text()));
        assert!(why.contains("panic = \"unwind\""), "{why}");
    }

    #[test]
    fn another_compiler_is_named() {
        let host = Fingerprint::host();
        let other = Fingerprint::from_text(&host.text().replace("rustc ", "rustc 9"));
        let why = other.mismatch(&host).unwrap();
        assert!(why.contains("`rustc 9"), "{why}");
        assert!(why.contains("rebuild it"), "{why}");
    }
}
