//! trybuild tests live in `tests/`.
//!
//! The derive's output compiles in edition 2021 crates too (the workspace is edition 2024);
//! rustdoc compiles this example as edition 2021:
//!
//! ```edition2021
//! use plc_core::{FixedString, GlobalMemory, ProcessImage, Value};
//!
//! type Word = u16;
//!
//! #[derive(GlobalMemory, Debug, Clone, PartialEq)]
//! pub struct Gm {
//!     /// Inputs of the IO module
//!     #[plc(link = "ethercat.io_0.inputs", direction = "input")]
//!     inputs: Word,
//!     #[plc(source = "inputs", bit = 3)]
//!     guard_closed: bool,
//!     #[plc(at = "%QW2", initial = -7)]
//!     analog_out: i16,
//!     #[plc(initial = "edition 2021", retain)]
//!     label: FixedString<16>,
//!     #[plc(iec_type = "WORD", initial = 0xff)]
//!     mode: u16,
//!     grid: [[[u8; 2]; 2]; 2],
//! }
//!
//! # fn main() {
//! let gen = 0; // `gen` is a keyword in edition 2024: this example really is edition 2021
//! let mut gm = Gm::default();
//! # let _ = gen;
//! assert_eq!((gm.analog_out, gm.label.as_str(), gm.mode), (-7, "edition 2021", 0xff));
//! gm.inputs = 1 << 3;
//! gm.unpack_bits();
//! assert!(gm.guard_closed);
//! let i = Gm::index_of("GRID").expect("case-insensitive lookup");
//! gm.set(i, 7, Value::UInt(9)).expect("last element");
//! assert_eq!(gm.grid[1][1][1], 9);
//! assert_eq!(Gm::from_image(&gm.to_image()), gm);
//! let mut q = [0u8; 4];
//! gm.write_outputs(&mut ProcessImage::new(&mut q[..])).expect("aligned %QW2");
//! assert_eq!(&q[2..], &(-7i16).to_be_bytes());
//! assert_eq!(Gm::VARIABLES[0].description, "Inputs of the IO module");
//! assert!(Gm::VARIABLES[3].nonvolatile);
//! # }
//! ```

/// The examples of `docs/structures.md`, compiled and run as doctests so the page stays true.
#[doc = include_str!("../../docs/structures.md")]
pub mod structures_doc {}

/// The examples of `docs/motion.md`, compiled and run as doctests so the page stays true.
#[doc = include_str!("../../docs/motion.md")]
pub mod motion_doc {}
