//! The segment's format: where every word is, the header, the status block and its types, the
//! descriptor, values in image bytes, the seqlock, the table of forces and a trace's ring.
//! Both sides write or read it; it knows neither.

pub mod bus_clocks;
pub mod bus_state;
pub mod bytes;
pub mod change;
pub mod codec;
pub mod cycle_stats;
pub mod descriptor;
pub mod force_table;
pub mod header;
pub mod io_status;
pub mod layout;
pub mod seqlock;
pub mod status;
pub mod trace_ring;
