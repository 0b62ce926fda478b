//! Ergonomics: what the fused 3D skeleton means for the operator's body.
//!
//! Will hold (issue "Ergonomics"): the complete RULA worksheet for both sides, joint angles from
//! BlazePose-33 landmarks, stature estimation and the height class at session start, and posture
//! warnings with hysteresis. Depends only on [`ergocell_skeleton`]; knows nothing of cameras, ROS or
//! the robot.
