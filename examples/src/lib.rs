//! Example programs of plc-vars live in `src/bin`.
