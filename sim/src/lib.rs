//! Digital twin of the cell: simulated operators, cameras and pose-estimator noise with ground truth.
//!
//! Will hold (issue "Digital twin"): anthropometric operators, task-driven postures, a camera rig from
//! `config/`, realistic 2D detections, and the seed paper's experiments. Deterministic: every run takes
//! a seed.
