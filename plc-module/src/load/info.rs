//! What a module says of itself, as the trial child reports it and a loaded module answers.

use plc_shm::LayoutDescriptor;

/// What a module says of itself, checked: from [`Module::inspect`](crate::Module::inspect)
/// (which loads no code into this process) or [`Module::info`](crate::Module::info).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ModuleInfo {
    /// The program crate's name.
    pub name: String,
    /// What built it.
    pub fingerprint: String,
    /// Its variables, as its segment publishes them.
    pub descriptor: LayoutDescriptor,
    /// The bus description it was compiled against: the path as written and the text.
    pub bus: Option<(String, String)>,
}
