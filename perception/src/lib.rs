//! Perception: from calibrated cameras and 2D body landmarks to one fused 3D skeleton.
