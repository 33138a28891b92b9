//! The `.babylon` scene loader (placeholder, being written).
