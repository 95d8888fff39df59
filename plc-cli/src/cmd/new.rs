//! `plc new NAME [--path CHECKOUT]`: a program module crate that `cargo build --release` turns
//! into `target/release/lib<NAME>.so`, which `plc run` starts at once on the simulated bus: a
//! struct linked to a bus description (an EK1100, an EL1004 and an EL2004, as `plc bus scan
//! --sim` writes it), a tick, and `plc_io::program!`.

use super::Error;
use std::path::{Path, PathBuf};

/// `plc new`.
#[derive(clap::Args)]
pub struct NewArgs {
    /// The crate's name (and its directory's): letters, digits, `-` and `_`, starting with a
    /// letter.
    pub name: String,
    /// The plc-vars checkout its dependencies point at; default: the one this `plc` was built
    /// from.
    #[arg(long, value_name = "CHECKOUT")]
    pub path: Option<PathBuf>,
}

const CARGO_TOML: &str = include_str!("../../templates/new/Cargo.toml");
const LIB_RS: &str = include_str!("../../templates/new/lib.rs");
const MACHINE_TOML: &str = include_str!("../../templates/new/machine.toml");

/// The checkout `plc` was built from (plc-cli's parent directory).
fn built_from() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

pub fn run(args: &NewArgs) -> Result<(), Error> {
    let name = &args.name;
    let valid = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
        && name.len() <= 64;
    if !valid {
        return Err(format!(
            "`{name}` is not a crate name: use letters, digits, `-` and `_`, starting with a \
             letter (at most 64)"
        )
        .into());
    }
    let checkout = std::path::absolute(args.path.clone().unwrap_or_else(built_from))?;
    if !checkout.join("plc-io/Cargo.toml").is_file() {
        return Err(format!(
            "`{}` is no plc-vars checkout (it has no plc-io/Cargo.toml): give one with --path",
            checkout.display()
        )
        .into());
    }
    let dir = Path::new(name);
    if dir.exists() {
        return Err(format!("`{name}` exists already: choose another name or remove it").into());
    }
    let checkout_text = checkout
        .to_str()
        .ok_or_else(|| format!("the checkout's path `{}` is not UTF-8", checkout.display()))?;
    let manifest = CARGO_TOML
        .replace("{name}", name)
        .replace("{lib}", &name.replace('-', "_"))
        .replace("{checkout}", &checkout_text.replace('\\', "/"));
    let lib = LIB_RS
        .replace("{name}", name)
        .replace("{lib}", &name.replace('-', "_"));
    std::fs::create_dir_all(dir.join("src"))?;
    std::fs::create_dir_all(dir.join("bus"))?;
    std::fs::write(dir.join("Cargo.toml"), manifest)?;
    std::fs::write(dir.join("src/lib.rs"), lib)?;
    std::fs::write(dir.join("bus/machine.toml"), MACHINE_TOML)?;
    std::fs::write(dir.join(".gitignore"), "/target\n")?;
    println!(
        "plc: wrote `{name}`, a program module on plc-vars at {checkout_text}; next:\n  \
         cd {name} && cargo build --release\n  plc run target/release/lib{}.so",
        name.replace('-', "_")
    );
    Ok(())
}
