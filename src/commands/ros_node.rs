//! The ROS 2 node of `run` and `replay`: its network scope and SROS2 enclave from `[ros]` and the
//! ROS 2 environment variables (read here, at the binary's boundary, and decided by
//! `ergocell_bridge`), the tokio runtime it spins on, and its orderly end.

use std::path::PathBuf;
use std::time::Duration;

use anyhow::Context as _;
use ergocell_bridge::transport::{DomainParticipant, RosConfig, RosNode};

use super::UsageError;

/// The runtime a node spins on: two workers.
pub fn runtime() -> anyhow::Result<tokio::runtime::Runtime> {
    tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .context("tokio runtime")
}

/// A started node: the node, the runtime it spins on, its DDS participant and its network scope.
/// Dropped without [`StartedNode::shut_down`] (an error before the sessions), its fields go in
/// this order: the node, the runtime, the participant last.
pub struct StartedNode {
    pub node: RosNode,
    pub runtime: tokio::runtime::Runtime,
    participant: DomainParticipant,
    pub scope: ergocell_bridge::scope::NetworkScope,
}

impl StartedNode {
    /// The node `name` of `ros`, in its network scope and SROS2 enclave (`keystore` from the command
    /// line, `[ros] keystore` relative to `config`'s folder, `default_enclave` unless overridden),
    /// spinning on `runtime`; whether DDS Security is on is said on stdout.
    pub fn start(
        runtime: tokio::runtime::Runtime,
        ros: &RosConfig,
        name: &str,
        config: &std::path::Path,
        keystore: Option<&std::path::Path>,
        default_enclave: &str,
    ) -> anyhow::Result<Self> {
        let scope = network_scope(ros)?;
        let enclave = security_enclave(ros, config, keystore, default_enclave)?;
        let mut node = RosNode::new(
            ros.domain_id,
            &ros.namespace,
            name,
            &scope,
            enclave.as_deref(),
        )?;
        let participant = node.participant();
        runtime.spawn(node.spinner()?);
        Ok(Self {
            node,
            runtime,
            participant,
            scope,
        })
    }

    /// The node first (it tells the spinner to stop), then a moment for the spinner to finish while
    /// the runtime still runs: every reader and writer says goodbye before the DDS participant goes,
    /// last (every entity has been removed from it: `RosNode::participant`).
    pub fn shut_down(self) {
        let Self {
            runtime,
            node,
            participant,
            ..
        } = self;
        drop(node);
        runtime.block_on(async { tokio::time::sleep(Duration::from_millis(100)).await });
        drop(runtime);
        drop(participant);
    }
}

/// Prints a line about the robot side, if there is one.
pub fn say(line: Option<String>) {
    if let Some(line) = line {
        println!("  {line}");
    }
}

/// The SROS2 enclave folder for this node, or `None` without DDS Security (said on stdout either way),
/// from `--keystore`, the ROS_SECURITY_* variables and `[ros]` (`security_required`, `keystore`
/// relative to the cell file's folder).
fn security_enclave(
    ros: &RosConfig,
    config: &std::path::Path,
    cli: Option<&std::path::Path>,
    default_enclave: &str,
) -> anyhow::Result<Option<PathBuf>> {
    use ergocell_bridge::security::{resolve_security, SecurityDecision, SecurityEnv};
    let var = |name: &str| std::env::var(name).ok();
    let env = SecurityEnv {
        enable: var("ROS_SECURITY_ENABLE"),
        strategy: var("ROS_SECURITY_STRATEGY"),
        keystore: var("ROS_SECURITY_KEYSTORE"),
        enclave_override: var("ROS_SECURITY_ENCLAVE_OVERRIDE"),
    };
    let config_keystore = ros.keystore.as_ref().map(|k| {
        config
            .parent()
            .unwrap_or_else(|| std::path::Path::new("."))
            .join(k)
    });
    let decision = resolve_security(
        ros.security_required,
        config_keystore.as_deref(),
        cli,
        default_enclave,
        &env,
        |dir| {
            ergocell_bridge::transport::ENCLAVE_FILES
                .iter()
                .all(|f| dir.join(f).is_file())
        },
    )
    .map_err(|e| UsageError(e.to_string()))?;
    Ok(match decision {
        SecurityDecision::Off(why) => {
            println!("{why}");
            None
        }
        SecurityDecision::Enclave { name, dir } => {
            println!(
                "DDS Security on: enclave {name} ({}): authenticated, access-controlled, encrypted",
                dir.display()
            );
            Some(dir)
        }
    })
}

/// The DDS participant's network scope from `[ros]` and the ROS 2 environment variables
/// (`ROS_AUTOMATIC_DISCOVERY_RANGE`, `ROS_STATIC_PEERS`, `ROS_LOCALHOST_ONLY`).
fn network_scope(ros: &RosConfig) -> anyhow::Result<ergocell_bridge::scope::NetworkScope> {
    let var = |name: &str| std::env::var(name).ok();
    let env = ergocell_bridge::scope::ScopeEnv {
        automatic_discovery_range: var("ROS_AUTOMATIC_DISCOVERY_RANGE"),
        static_peers: var("ROS_STATIC_PEERS"),
        localhost_only: var("ROS_LOCALHOST_ONLY"),
    };
    Ok(ergocell_bridge::scope::NetworkScope::resolve(
        ros.discovery_range,
        ros.interfaces.as_deref(),
        &env,
    )?)
}
