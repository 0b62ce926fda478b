//! ROS 2 bridge: the messages and transport between ergocell, the camera nodes and the KUKA controller.
//!
//! Will hold (issue "The cell controller"): hand-written ROS 2 message structs in IDL field order, the
//! `ros2-client` transport, and QoS choices. The only library crate that touches the network.
