//! The trial child for hosts that are not `plc` (this crate's tests): a program that loads
//! modules may run this instead of itself (`Trial::with_program`).

fn main() {
    plc_module::trial::serve_if_asked();
    eprintln!(
        "plc-module-trial: started without `{}`: it only tries modules for a host",
        plc_module::trial::TRIAL_ARG
    );
    std::process::exit(2);
}
