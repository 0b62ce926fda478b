//! ROS 2 transport with `ros2-client` (pure-Rust DDS, no ROS installation): the cell node's topics
//! and the camera-replay node's. Topic names come from [`RosConfig`] (`[ros]` in `config/cell.toml`);
//! QoS from [`crate::qos`].
//!
//! Holding the robot publishes an empty `JointTrajectory` on the controller's topic (the
//! ros2_control joint trajectory controller then drops its goal and stops). It is not an emergency
//! stop; that stays with the robot's safety controller.

/// The DDS participant a [`RosNode`] lives in (dropped last: [`RosNode::participant`]).
pub use ros2_client::dds::rustdds::DomainParticipant;
use ros2_client::{Context, MessageTypeName, Name, Node, NodeName, NodeOptions, QosProfile};
pub use ros2_client::{Publisher, Subscription};
use serde::Deserialize;

use crate::msg::{
    BoolMsg, CameraLandmarks, ControllerEvent, ErgonomicState, HardwareEvent, JointState,
    JointTrajectory, MarkerArray, PostureWarning, RebaState, RosMessage, SessionState,
};
use crate::qos::{self, TopicQos};
use crate::scope::{DiscoveryRange, NetworkScope};
use crate::topics;
use crate::BridgeError;

/// `[ros]` of `config/cell.toml`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RosConfig {
    /// DDS domain (ROS_DOMAIN_ID is not read: it is configured here).
    #[serde(default)]
    pub domain_id: u16,
    /// Node namespace and name of the cell controller.
    #[serde(default = "default_namespace")]
    pub namespace: String,
    #[serde(default = "default_node")]
    pub node_name: String,
    /// Camera ids (one topic each); must match the rig's camera ids.
    pub cameras: Vec<String>,
    /// Camera topic, `{id}` replaced by the camera id.
    #[serde(default = "default_camera_topic")]
    pub camera_topic: String,
    #[serde(default = "default_joint_states")]
    pub joint_states_topic: String,
    #[serde(default = "default_joint_trajectory")]
    pub joint_trajectory_topic: String,
    /// The FollowJointTrajectory action of the controller (used when `robot_interface = "action"`).
    #[serde(default = "default_action")]
    pub follow_joint_trajectory_action: String,
    /// How the robot is commanded: `topic` (the controller's `joint_trajectory` topic, fire and
    /// forget) or `action` (FollowJointTrajectory: acceptance, feedback, result, tolerances; a
    /// rejected, aborted or unanswered goal holds the robot and ends the session).
    #[serde(default)]
    pub robot_interface: RobotInterface,
    /// The controller's ROS 2 distribution, for control_msgs' Feedback layout (`jazzy`, `humble`:
    /// without `index`; `kilted`, `rolling`: with it).
    #[serde(default = "default_distro")]
    pub distro: String,
    /// The goal's path tolerance per joint (radians): the largest deviation while it runs.
    #[serde(default = "default_path_tolerance")]
    pub path_tolerance_rad: f64,
    /// At most this goal tolerance per joint at a leg's end (radians): tightens the lock's
    /// (`[monitor] goal_tolerance_rad` when it was locked); unset, the lock's holds.
    #[serde(default)]
    pub goal_tolerance_rad: Option<f64>,
    /// At most this late after a leg's last point (seconds): tightens the lock's.
    #[serde(default)]
    pub goal_time_tolerance_s: Option<f64>,
    /// The execution monitor (`ergocell_robot::monitor`): every `/joint_states` sample against the
    /// locked leg; a deviation cancels and holds, and ends the session.
    #[serde(default = "default_true")]
    pub monitor_execution: bool,
    /// Joint states older than this (seconds) are stale: the robot is held until they are back.
    #[serde(default = "default_joint_state_timeout")]
    pub joint_state_timeout_s: f64,
    /// At rest (a leg arrived, a hold stopped), at most this motion (radians): tightens the lock's.
    #[serde(default)]
    pub rest_tolerance_rad: Option<f64>,
    /// A stall is judged over at most this window (seconds): tightens the lock's.
    #[serde(default)]
    pub stall_window_s: Option<f64>,
    /// After a hold, at most this time to come to rest (seconds): tightens the lock's.
    #[serde(default)]
    pub stop_time_s: Option<f64>,
    /// Read the KUKA driver's state (kuka_drivers conventions) and send no goal unless it is
    /// configured and controlling; "stopped by user" or "stopped by error" hold the robot.
    #[serde(default)]
    pub driver_state: bool,
    #[serde(default = "default_is_configured")]
    pub is_configured_topic: String,
    #[serde(default = "default_hardware_event")]
    pub hardware_event_topic: String,
    /// The robot side's events: goal answers, cancels, monitor verdicts, driver changes.
    #[serde(default = "default_controller_events")]
    pub controller_events_topic: String,
    #[serde(default = "default_session_state")]
    pub session_state_topic: String,
    /// Every session event in order (the same `SessionState` messages, deeper history).
    #[serde(default = "default_session_events")]
    pub session_events_topic: String,
    #[serde(default = "default_ergonomics")]
    pub ergonomics_topic: String,
    /// REBA beside RULA (`ergocell_msgs/RebaState`), one per assessed frame.
    #[serde(default = "default_reba")]
    pub reba_topic: String,
    #[serde(default = "default_warnings")]
    pub warnings_topic: String,
    /// The fused skeleton (`visualization_msgs/MarkerArray`, Jazzy layout) for RViz and Foxglove.
    #[serde(default = "default_skeleton")]
    pub skeleton_topic: String,
    /// How far discovery reaches (`subnet`, `localhost`, `off`, `system_default`); the environment's
    /// `ROS_AUTOMATIC_DISCOVERY_RANGE` must agree when both are set ([`crate::scope`]).
    #[serde(default)]
    pub discovery_range: Option<DiscoveryRange>,
    /// The cell network's interfaces, by this machine's IPv4 address on each: DDS multicasts and
    /// advertises only there (default: every interface).
    #[serde(default)]
    pub interfaces: Option<Vec<std::net::Ipv4Addr>>,
    /// Refuse to start `run` or `replay --ros` without DDS Security (SROS2).
    #[serde(default)]
    pub security_required: bool,
    /// The SROS2 keystore (relative to the cell file's folder); `--keystore` and
    /// `ROS_SECURITY_KEYSTORE` take precedence ([`crate::security::resolve_security`]).
    #[serde(default)]
    pub keystore: Option<std::path::PathBuf>,
}

fn default_namespace() -> String {
    topics::NAMESPACE.into()
}
fn default_node() -> String {
    "cell".into()
}
fn default_camera_topic() -> String {
    topics::CAMERA_PATTERN.into()
}
fn default_joint_states() -> String {
    topics::JOINT_STATES.into()
}
fn default_joint_trajectory() -> String {
    topics::JOINT_TRAJECTORY.into()
}
fn default_action() -> String {
    topics::FOLLOW_JOINT_TRAJECTORY.into()
}
/// How the robot is commanded ([`RosConfig::robot_interface`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RobotInterface {
    /// The controller's `joint_trajectory` topic (fire and forget).
    #[default]
    Topic,
    /// The controller's FollowJointTrajectory action.
    Action,
}

fn default_distro() -> String {
    "jazzy".into()
}
fn default_path_tolerance() -> f64 {
    0.05
}
fn default_true() -> bool {
    true
}
fn default_joint_state_timeout() -> f64 {
    0.1
}
fn default_is_configured() -> String {
    topics::IS_CONFIGURED.to_owned()
}
fn default_hardware_event() -> String {
    topics::HARDWARE_EVENT.to_owned()
}
fn default_controller_events() -> String {
    topics::CONTROLLER_EVENTS.to_owned()
}
fn default_session_state() -> String {
    topics::SESSION_STATE.into()
}
fn default_session_events() -> String {
    topics::SESSION_EVENTS.into()
}
fn default_ergonomics() -> String {
    topics::ERGONOMICS.into()
}
fn default_reba() -> String {
    topics::REBA.into()
}
fn default_warnings() -> String {
    topics::WARNINGS.into()
}
fn default_skeleton() -> String {
    topics::SKELETON.into()
}

#[derive(Deserialize)]
struct CellFile {
    ros: Option<RosConfig>,
}

/// The largest DDS domain id ROS 2 allows: RTPS puts domain `d`'s ports at 7400 + 250·d + …, and
/// above 232 they leave the 16-bit port range (ROS 2 "The ROS_DOMAIN_ID": 0–232, 0–101 safe on Linux).
pub const MAX_DOMAIN_ID: u16 = 232;

impl RosConfig {
    /// The `[ros]` table of a cell config file (other tables are read by other crates).
    pub fn from_cell_toml(text: &str) -> Result<Self, BridgeError> {
        let file: CellFile =
            toml::from_str(text).map_err(|e| BridgeError::Config(e.to_string()))?;
        let cfg = file
            .ros
            .ok_or_else(|| BridgeError::Config("no [ros] table".to_owned()))?;
        if cfg.cameras.is_empty() {
            return Err(BridgeError::Config("[ros] cameras is empty".to_owned()));
        }
        if !cfg.camera_topic.contains("{id}") {
            // Every camera would publish on, and the cell subscribe to, one topic: the views of
            // different cameras would be told apart only by the message's camera_id, and one
            // camera's message rate would count for all (the edge node refuses it too).
            return Err(BridgeError::Config(format!(
                "[ros] camera_topic = {:?}: must contain {{id}} (each camera's own topic, e.g. \
                 \"/ergocell/camera/{{id}}/landmarks\")",
                cfg.camera_topic
            )));
        }
        if cfg.domain_id > MAX_DOMAIN_ID {
            return Err(BridgeError::Config(format!(
                "[ros] domain_id = {}: ROS 2 allows 0..={MAX_DOMAIN_ID} (above, the DDS ports run past \
                 65535 and wrap onto other domains')",
                cfg.domain_id
            )));
        }
        if cfg.feedback_layout().is_none() {
            return Err(BridgeError::Config(format!(
                "[ros] distro = {:?}: expected humble, jazzy, kilted or rolling",
                cfg.distro
            )));
        }
        if let Some(v) = cfg.stall_window_s {
            return Err(BridgeError::Config(format!(
                "[ros] stall_window_s = {v}: the stall window is the trajectory lock's alone (set \
                 [monitor] stall_window_s and lock again): a shorter window misses stalls on slow \
                 legs, so it cannot be tightened here"
            )));
        }
        // (key, value, least, least allowed)
        let checks = [
            (
                "path_tolerance_rad",
                Some(cfg.path_tolerance_rad),
                0.0,
                false,
            ),
            (
                "joint_state_timeout_s",
                Some(cfg.joint_state_timeout_s),
                0.0,
                false,
            ),
            ("goal_tolerance_rad", cfg.goal_tolerance_rad, 0.0, false),
            // control_msgs reads a zero goal time tolerance as the action server's default
            (
                "goal_time_tolerance_s",
                cfg.goal_time_tolerance_s,
                0.001,
                true,
            ),
            ("rest_tolerance_rad", cfg.rest_tolerance_rad, 0.0, false),
            ("stop_time_s", cfg.stop_time_s, 0.0, true),
        ];
        for (key, value, least, least_ok) in checks {
            let Some(value) = value else { continue };
            let low_ok = if least_ok {
                value >= least
            } else {
                value > least
            };
            if !(value.is_finite() && low_ok && value <= 10.0) {
                return Err(BridgeError::Config(format!(
                    "[ros] {key} = {value}: expected a finite number {} {least}, at most 10",
                    if least_ok { ">=" } else { ">" }
                )));
            }
        }
        Ok(cfg)
    }

    /// The controller's FollowJointTrajectory Feedback layout (from `distro`).
    pub fn feedback_layout(&self) -> Option<crate::action::FeedbackLayout> {
        crate::action::FeedbackLayout::for_distro(&self.distro)
    }

    /// The topic of one camera.
    pub fn camera_topic_of(&self, id: &str) -> String {
        self.camera_topic.replace("{id}", id)
    }
}

fn profile(q: TopicQos) -> QosProfile {
    let reliability = match q.reliability {
        qos::Reliability::BestEffort => ros2_client::qos::Reliability::BestEffort,
        qos::Reliability::Reliable => ros2_client::qos::Reliability::Reliable {
            when_full: ros2_client::qos::WhenFull::DEFAULT,
        },
    };
    let durability = match q.durability {
        qos::Durability::Volatile => ros2_client::qos::Durability::Volatile,
        qos::Durability::TransientLocal => ros2_client::qos::Durability::TransientLocal,
    };
    QosProfile::subscription_default()
        .reliability(reliability)
        .durability(durability)
        .history(ros2_client::qos::History::KeepLast {
            depth: q.depth as usize,
        })
}

fn name_of(full: &str) -> Result<Name, BridgeError> {
    let (ns, base) = full.rsplit_once('/').unwrap_or(("", full));
    let ns = if ns.is_empty() { "/" } else { ns };
    Name::new(ns, base).map_err(|e| BridgeError::Ros(format!("topic name {full}: {e:?}")))
}

fn ros_err(what: &str) -> impl Fn(String) -> BridgeError + '_ {
    move |e| BridgeError::Ros(format!("{what}: {e}"))
}

/// The files of an SROS2 enclave folder that DDS Security reads.
pub const ENCLAVE_FILES: [&str; 6] = [
    "identity_ca.cert.pem",
    "cert.pem",
    "key.pem",
    "permissions_ca.cert.pem",
    "governance.p7s",
    "permissions.p7s",
];

/// A ROS 2 node with helpers to make typed publishers and subscriptions.
pub struct RosNode {
    pub node: Node,
    context: Context,
}

impl RosNode {
    /// A handle on the node's DDS participant. Hold it until the node, every reader and writer,
    /// and the runtime that spun them are dropped, then drop it: the participant's event loop
    /// then outlives every entity, which says goodbye to it (ros2-client 0.12 drops its context's
    /// participant before the node's own parameter-service readers and writers, and each of those
    /// then logs "Cannot remove Writer/Reader …: Disconnected" at ERROR level on a clean exit).
    pub fn participant(&self) -> ros2_client::dds::rustdds::DomainParticipant {
        self.context.domain_participant()
    }

    /// Creates the node, its DDS participant confined to `scope` and, with `enclave` (an SROS2
    /// enclave folder: `cert.pem`, `key.pem`, the CA certificates, `governance.p7s`,
    /// `permissions.p7s`), authenticated, access-controlled and encrypted by DDS Security; spawn
    /// [`RosNode::spinner`] on the runtime before use.
    pub fn new(
        domain_id: u16,
        namespace: &str,
        name: &str,
        scope: &NetworkScope,
        enclave: Option<&std::path::Path>,
    ) -> Result<Self, BridgeError> {
        let (only, same_host) = scope.participant_filter();
        let mut builder = ros2_client::dds::rustdds::DomainParticipantBuilder::new(domain_id)
            .same_host_loopback(same_host);
        if let Some(addrs) = only {
            builder = builder.with_only_networks(addrs);
        }
        if let Some(dir) = enclave {
            for file in ENCLAVE_FILES {
                if !dir.join(file).is_file() {
                    return Err(BridgeError::Config(format!(
                        "SROS2 enclave {}: no {file} (create one with `ergocell security create-keystore`)",
                        dir.display()
                    )));
                }
            }
            builder = builder.builtin_security(
                ros2_client::dds::rustdds::DomainParticipantSecurityConfigFiles::with_ros_default_names(
                    dir,
                    String::new(),
                ),
            );
        }
        let participant = builder
            .build()
            .map_err(|e| BridgeError::Ros(format!("DDS participant ({scope}): {e:?}")))?;
        let context = Context::from_domain_participant(participant)
            .map_err(|e| BridgeError::Ros(format!("DDS context: {e:?}")))?;
        let node_name = NodeName::new(namespace, name)
            .map_err(|e| BridgeError::Ros(format!("node name {namespace}/{name}: {e:?}")))?;
        let node = context
            .new_node(
                node_name,
                NodeOptions::new()
                    .enable_rosout(false)
                    .start_parameter_services(false),
            )
            .map_err(|e| BridgeError::Ros(format!("node: {e:?}")))?;
        Ok(Self { node, context })
    }

    /// The spinner future (discovery, parameters); spawn it on the runtime.
    pub fn spinner(
        &mut self,
    ) -> Result<impl std::future::Future<Output = ()> + Send + 'static, BridgeError> {
        let spinner = self
            .node
            .spinner()
            .map_err(|e| BridgeError::Ros(format!("spinner: {e:?}")))?;
        Ok(async move {
            if let Err(e) = spinner.spin().await {
                tracing::error!(error = ?e, "ROS 2 spinner stopped");
            }
        })
    }

    /// A publisher of `M` on `topic` with `qos`.
    pub fn publisher<M: RosMessage>(
        &mut self,
        topic: &str,
        qos: TopicQos,
    ) -> Result<Publisher<M>, BridgeError> {
        let q = profile(qos);
        let t = self
            .node
            .create_topic(
                &name_of(topic)?,
                MessageTypeName::new(M::PACKAGE, M::NAME),
                &q,
            )
            .map_err(|e| ros_err(topic)(format!("{e:?}")))?;
        self.node
            .create_publisher(&t, Some(q))
            .map_err(|e| ros_err(topic)(format!("{e:?}")))
    }

    /// A FollowJointTrajectory client on `action` (e.g.
    /// `/joint_trajectory_controller/follow_joint_trajectory`), Feedback layout `F`.
    pub fn follow_joint_trajectory_client<F: ros2_client::Message + 'static>(
        &mut self,
        action: &str,
    ) -> Result<crate::controller::FjtClient<F>, BridgeError> {
        let services = profile(qos::ACTION_SERVICES);
        let status = profile(qos::ACTION_STATUS);
        self.node
            .create_action_client(
                ros2_client::ServiceMapping::Enhanced,
                &name_of(action)?,
                &ros2_client::ActionTypeName::new("control_msgs", "FollowJointTrajectory"),
                ros2_client::action::ActionClientQosPolicies {
                    goal_service: services.clone(),
                    result_service: services.clone(),
                    cancel_service: services.clone(),
                    feedback_subscription: services,
                    status_subscription: status,
                },
            )
            .map_err(|e| ros_err(action)(format!("{e:?}")))
    }

    /// A subscription to `M` on `topic` with `qos`.
    pub fn subscription<M: RosMessage + 'static>(
        &mut self,
        topic: &str,
        qos: TopicQos,
    ) -> Result<Subscription<M>, BridgeError> {
        let q = profile(qos);
        let t = self
            .node
            .create_topic(
                &name_of(topic)?,
                MessageTypeName::new(M::PACKAGE, M::NAME),
                &q,
            )
            .map_err(|e| ros_err(topic)(format!("{e:?}")))?;
        self.node
            .create_subscription(&t, Some(q))
            .map_err(|e| ros_err(topic)(format!("{e:?}")))
    }
}

/// The cell controller's topics.
pub struct CellTopics {
    pub cameras: Vec<Subscription<CameraLandmarks>>,
    pub joint_states: Subscription<JointState>,
    /// The robot's command (the robot sink's: every command, or a hold's empty trajectory).
    pub joint_trajectory: Publisher<JointTrajectory>,
    /// What the cell publishes of its sessions.
    pub publishers: CellPublishers,
    /// With `driver_state`: kuka_drivers' `is_configured` and `hardware_event`.
    pub driver: Option<(Subscription<BoolMsg>, Subscription<HardwareEvent>)>,
}

/// What the cell publishes of its sessions (the robot command aside).
pub struct CellPublishers {
    pub session_state: Publisher<SessionState>,
    /// The same messages, every one (deeper history).
    pub session_events: Publisher<SessionState>,
    pub ergonomics: Publisher<ErgonomicState>,
    pub reba: Publisher<RebaState>,
    pub warnings: Publisher<PostureWarning>,
    pub skeleton: Publisher<MarkerArray>,
    pub controller_events: Publisher<ControllerEvent>,
}

impl CellTopics {
    /// Creates every publisher and subscription of the cell node, QoS from [`crate::qos`].
    pub fn new(node: &mut RosNode, cfg: &RosConfig) -> Result<Self, BridgeError> {
        let cameras = cfg
            .cameras
            .iter()
            .map(|id| node.subscription(&cfg.camera_topic_of(id), qos::CAMERA_LANDMARKS))
            .collect::<Result<Vec<_>, _>>()?;
        let publishers = CellPublishers {
            session_state: node.publisher(&cfg.session_state_topic, qos::SESSION_STATE)?,
            session_events: node.publisher(&cfg.session_events_topic, qos::SESSION_EVENTS)?,
            ergonomics: node.publisher(&cfg.ergonomics_topic, qos::PER_FRAME_STATE)?,
            reba: node.publisher(&cfg.reba_topic, qos::PER_FRAME_STATE)?,
            warnings: node.publisher(&cfg.warnings_topic, qos::WARNINGS)?,
            skeleton: node.publisher(&cfg.skeleton_topic, qos::PER_FRAME_STATE)?,
            controller_events: node
                .publisher(&cfg.controller_events_topic, qos::CONTROLLER_EVENTS)?,
        };
        Ok(Self {
            cameras,
            joint_states: node.subscription(&cfg.joint_states_topic, qos::JOINT_STATES)?,
            joint_trajectory: node
                .publisher(&cfg.joint_trajectory_topic, qos::TRAJECTORY_COMMAND)?,
            publishers,
            driver: if cfg.driver_state {
                Some((
                    node.subscription(&cfg.is_configured_topic, qos::DRIVER_STATE)?,
                    node.subscription(&cfg.hardware_event_topic, qos::DRIVER_STATE)?,
                ))
            } else {
                None
            },
        })
    }
}

/// Publishes `message`, mapping the error.
pub async fn publish<M: serde::Serialize + std::fmt::Debug>(
    p: &Publisher<M>,
    message: M,
) -> Result<(), BridgeError> {
    p.async_publish(message)
        .await
        .map_err(|e| BridgeError::Ros(format!("publish: {e:?}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_robot_interface_distro_and_tolerances_parse_and_bad_ones_are_refused() {
        let base = "[ros]\ncameras = [\"a\"]\n";
        let cfg = RosConfig::from_cell_toml(base).unwrap();
        assert_eq!(cfg.robot_interface, RobotInterface::Topic);
        assert_eq!(
            cfg.feedback_layout(),
            Some(crate::action::FeedbackLayout::WithoutIndex)
        );
        assert_eq!(cfg.path_tolerance_rad, 0.05);
        assert_eq!(cfg.goal_tolerance_rad, None, "unset: the lock's holds");
        let action = RosConfig::from_cell_toml(&format!(
            "{base}robot_interface = \"action\"\ndistro = \"kilted\"\npath_tolerance_rad = 0.02\n"
        ))
        .unwrap();
        assert_eq!(action.robot_interface, RobotInterface::Action);
        assert_eq!(
            action.feedback_layout(),
            Some(crate::action::FeedbackLayout::WithIndex)
        );
        assert_eq!(action.path_tolerance_rad, 0.02);
        for (bad, says) in [
            ("distro = \"iron\"", "distro"),
            ("robot_interface = \"service\"", "robot_interface"),
            ("path_tolerance_rad = 0.0", "path_tolerance_rad"),
            ("goal_tolerance_rad = nan", "goal_tolerance_rad"),
            ("goal_time_tolerance_s = -1.0", "goal_time_tolerance_s"),
            ("goal_time_tolerance_s = 0.0", "goal_time_tolerance_s"),
            ("stall_window_s = 0.05", "stall_window_s"),
        ] {
            let e = RosConfig::from_cell_toml(&format!("{base}{bad}\n")).unwrap_err();
            assert!(e.to_string().contains(says), "{bad}: {e}");
        }
    }

    #[test]
    fn ros_table_parses_with_defaults_and_rejects_unknown_keys() {
        let cfg = RosConfig::from_cell_toml(
            "[robot]\nurdf = \"x\"\n[ros]\ncameras = [\"a\", \"b\"]\ndomain_id = 7\n",
        )
        .unwrap();
        assert_eq!(cfg.domain_id, 7);
        assert_eq!(cfg.camera_topic_of("a"), "/ergocell/camera/a/landmarks");
        assert_eq!(
            cfg.joint_trajectory_topic,
            "/joint_trajectory_controller/joint_trajectory"
        );
        assert!(RosConfig::from_cell_toml("[ros]\ncameras = [\"a\"]\ntypo = 1\n").is_err());
        assert!(RosConfig::from_cell_toml("[robot]\n").is_err());
        assert!(RosConfig::from_cell_toml("[ros]\ncameras = []\n").is_err());
        let one_topic = RosConfig::from_cell_toml(
            "[ros]\ncameras = [\"a\", \"b\"]\ncamera_topic = \"/cams/landmarks\"\n",
        )
        .unwrap_err()
        .to_string();
        assert!(
            one_topic.contains("camera_topic") && one_topic.contains("{id}"),
            "{one_topic}"
        );
        let domain = |id: u32| {
            RosConfig::from_cell_toml(&format!("[ros]\ncameras = [\"a\"]\ndomain_id = {id}\n"))
        };
        assert_eq!(domain(232).unwrap().domain_id, 232);
        for id in [233, 250] {
            let e = domain(id).unwrap_err().to_string();
            assert!(e.contains("domain_id = ") && e.contains("0..=232"), "{e}");
        }
    }

    #[test]
    fn topic_names_split_into_namespace_and_base() {
        assert!(name_of("/joint_states").is_ok());
        assert!(name_of("/joint_trajectory_controller/joint_trajectory").is_ok());
        assert!(name_of("/ergocell/camera/s1_left/landmarks").is_ok());
    }
}
