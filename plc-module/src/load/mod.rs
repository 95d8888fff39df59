//! The host's side: from a module file to a [`Module`](module::Module) that runs, through
//! the file's checks (`file`), its ELF headers (`elf`), a sealed copy (`sealed`), a trial in
//! a child (`trial`) and the loader with the entry's checks (`library`).

mod elf;
pub mod error;
mod file;
pub mod info;
mod library;
pub mod module;
mod sealed;
pub mod trial;
pub mod trial_child;
