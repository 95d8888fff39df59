//! The segment's format: where every word is, the header, the status block and its types, the
//! descriptor, values in image bytes, the seqlock, the tables of forces and alarm states and
//! a trace's ring.
//! Both sides write or read it; it knows neither.

pub mod alarm_descriptor;
pub mod alarm_table;
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
