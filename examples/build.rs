//! Generates into `OUT_DIR` the structs of `project.json` (a JSON variable list) and
//! `project.csv` (the same kind of list kept as a spreadsheet), as a project moving from such a
//! file would (edit the file, rebuild).

fn main() {
    let out =
        std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("OUT_DIR is set by cargo"));
    for (input, output) in [
        ("project.json", "project.rs"),
        ("project.csv", "project_csv.rs"),
    ] {
        if let Err(e) = plc_io::import::generate_from_file(input.as_ref(), &out.join(output)) {
            eprintln!("{e}");
            std::process::exit(1);
        }
    }
}
