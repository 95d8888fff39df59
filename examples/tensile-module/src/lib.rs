//! The tensile tester as a program module: the same variables and tick as the linked binary
//! (`examples/src/bin/tensile_tester.rs`), exported for a host through `plc_io::program!`.

plc_io::program!(examples::tensile::Gm, examples::tensile::tick);
