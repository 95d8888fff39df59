//! Generates into `OUT_DIR` the `Gm1k` and structure benchmark workloads (`src/workload.rs`).

#[path = "src/workload.rs"]
mod workload;

fn main() {
    let out =
        std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR is set by cargo"));
    println!("cargo:rerun-if-changed=src/workload.rs");
    let gm1k = workload::source(1, "crate::cycle::HandWritten");
    let axes = workload::axes_source(100);
    for (file, text) in [("gm1k.rs", gm1k), ("axes.rs", axes)] {
        if let Err(e) = std::fs::write(out.join(file), text) {
            eprintln!("{}: {e}", out.join(file).display());
            std::process::exit(1);
        }
    }
}
