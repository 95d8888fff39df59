//! Placeholder: the simulated bus lands with its issue.
