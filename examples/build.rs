//! Generates the struct of `project.json` (seed 000's JSON variable list) into `OUT_DIR`, as a
//! project moving from a JSON file would: edit the JSON, rebuild.

fn main() {
    let out =
        std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR is set by cargo"));
    if let Err(e) =
        plc_io::import::generate_from_file("project.json".as_ref(), &out.join("project.rs"))
    {
        eprintln!("{e}");
        std::process::exit(1);
    }
}
