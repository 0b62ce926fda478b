//! Which networks the cell's DDS participant may use: ROS 2's discovery range, honoured.
//!
//! RustDDS, left alone, joins discovery multicast on every multicast-capable interface and advertises
//! every IPv4 address: a robot PC with one leg on the cell's network and one on the plant LAN announces
//! the cell, its topics and the operator's posture stream on both. ROS 2 (Iron and later) says how far
//! discovery may reach with two variables, which ergocell honours like any ROS 2 node, and the cell
//! config can pin the interfaces:
//!
//! - `ROS_AUTOMATIC_DISCOVERY_RANGE`: `SUBNET` (the default: every interface, or the configured ones),
//!   `LOCALHOST` (this machine only: the loopback interface, and RustDDS's same-host peers),
//!   `OFF` (no automatic discovery at all, not even on this machine), `SYSTEM_DEFAULT` (the DDS
//!   implementation's own default, i.e. RustDDS untouched). The deprecated `ROS_LOCALHOST_ONLY=1`
//!   means `LOCALHOST`.
//! - `ROS_STATIC_PEERS` (`;`-separated addresses to reach whatever the range): RustDDS 0.15 has no
//!   initial-peers list, so a non-empty value is refused with that reason rather than ignored.
//! - `[ros] discovery_range` and `[ros] interfaces` (IPv4 addresses of this machine's cell-network
//!   interfaces) in the cell config. When the config and the environment both set a range and they
//!   differ, the start is refused: the narrower intent is not guessed.
//!
//! This module decides; [`crate::transport::RosNode`] applies it to the participant. It reads no
//! environment (the binary reads it and passes the values in); its one contact with the network is
//! [`multicast_note`], which asks the kernel once whether discovery's multicast group can be joined.

use std::fmt;
use std::net::{IpAddr, Ipv4Addr};

use serde::Deserialize;

use crate::BridgeError;

/// How far automatic discovery reaches (`ROS_AUTOMATIC_DISCOVERY_RANGE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DiscoveryRange {
    /// Every interface (or `[ros] interfaces`): ROS 2's default.
    Subnet,
    /// This machine only.
    Localhost,
    /// No automatic discovery.
    Off,
    /// The DDS implementation's own default (RustDDS untouched).
    SystemDefault,
}

impl DiscoveryRange {
    /// Parses the environment variable's value (case-insensitive; empty = not set).
    pub fn from_env_value(value: &str) -> Result<Option<Self>, BridgeError> {
        match value.trim().to_ascii_uppercase().as_str() {
            "" => Ok(None),
            "SUBNET" => Ok(Some(Self::Subnet)),
            "LOCALHOST" => Ok(Some(Self::Localhost)),
            "OFF" => Ok(Some(Self::Off)),
            "SYSTEM_DEFAULT" => Ok(Some(Self::SystemDefault)),
            other => Err(BridgeError::Config(format!(
                "ROS_AUTOMATIC_DISCOVERY_RANGE={other}: expected SUBNET, LOCALHOST, OFF or SYSTEM_DEFAULT"
            ))),
        }
    }
}

impl fmt::Display for DiscoveryRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Subnet => "SUBNET",
            Self::Localhost => "LOCALHOST",
            Self::Off => "OFF",
            Self::SystemDefault => "SYSTEM_DEFAULT",
        })
    }
}

/// The environment's say, as the binary read it.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ScopeEnv {
    /// `ROS_AUTOMATIC_DISCOVERY_RANGE`.
    pub automatic_discovery_range: Option<String>,
    /// `ROS_STATIC_PEERS`.
    pub static_peers: Option<String>,
    /// `ROS_LOCALHOST_ONLY` (deprecated; `1` = LOCALHOST).
    pub localhost_only: Option<String>,
}

/// What the participant may use, decided from the config and the environment.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NetworkScope {
    pub range: DiscoveryRange,
    /// For `SUBNET`: only these addresses' interfaces (`None`: all).
    pub interfaces: Option<Vec<Ipv4Addr>>,
}

impl NetworkScope {
    /// Decides the scope: `config_range` / `config_interfaces` from `[ros]`, `env` from the process.
    pub fn resolve(
        config_range: Option<DiscoveryRange>,
        config_interfaces: Option<&[Ipv4Addr]>,
        env: &ScopeEnv,
    ) -> Result<Self, BridgeError> {
        if let Some(peers) = env.static_peers.as_deref().filter(|p| !p.trim().is_empty()) {
            return Err(BridgeError::Config(format!(
                "ROS_STATIC_PEERS={peers}: static peers are not supported (RustDDS 0.15 has no initial-peers list); \
                 unset it and put the peers on the cell network (SUBNET, [ros] interfaces)"
            )));
        }
        let mut env_range = match env.automatic_discovery_range.as_deref() {
            Some(v) => DiscoveryRange::from_env_value(v)?,
            None => None,
        };
        if env_range.is_none() && env.localhost_only.as_deref().map(str::trim) == Some("1") {
            env_range = Some(DiscoveryRange::Localhost);
        }
        let range = match (config_range, env_range) {
            (Some(c), Some(e)) if c != e => {
                return Err(BridgeError::Config(format!(
                    "ROS_AUTOMATIC_DISCOVERY_RANGE={e} contradicts [ros] discovery_range = \"{}\" in the cell config: unset one",
                    c.to_string().to_ascii_lowercase()
                )))
            }
            (Some(c), _) => c,
            (None, Some(e)) => e,
            (None, None) => DiscoveryRange::Subnet,
        };
        let interfaces = config_interfaces.map(<[Ipv4Addr]>::to_vec);
        if let Some(list) = &interfaces {
            if list.is_empty() {
                return Err(BridgeError::Config(
                    "[ros] interfaces is empty: list the cell network's addresses, or leave it out for all".to_owned(),
                ));
            }
            if let Some(bad) = list.iter().find(|a| a.is_unspecified() || a.is_multicast()) {
                return Err(BridgeError::Config(format!(
                    "[ros] interfaces: {bad} is not an interface address"
                )));
            }
        }
        Ok(Self { range, interfaces })
    }

    /// The addresses RustDDS may use for multicast and advertise (`with_only_networks`), `None` for
    /// all of them; and whether same-host loopback discovery stays on.
    pub fn participant_filter(&self) -> (Option<Vec<IpAddr>>, bool) {
        match self.range {
            DiscoveryRange::Subnet => (
                self.interfaces
                    .as_ref()
                    .map(|l| l.iter().copied().map(IpAddr::V4).collect()),
                true,
            ),
            DiscoveryRange::Localhost => (Some(vec![IpAddr::V4(Ipv4Addr::LOCALHOST)]), true),
            DiscoveryRange::Off => (Some(Vec::new()), false),
            DiscoveryRange::SystemDefault => (None, true),
        }
    }
}

impl fmt::Display for NetworkScope {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "discovery range {}", self.range)?;
        match (&self.range, &self.interfaces) {
            (DiscoveryRange::Subnet, Some(list)) => write!(
                f,
                " on {}",
                list.iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            (DiscoveryRange::Subnet, None) => f.write_str(" on every interface"),
            _ => Ok(()),
        }
    }
}

/// DDS discovery's multicast group (SPDP, every domain: RTPS 2.x §9.6.1.4.1).
const DISCOVERY_GROUP: std::net::Ipv4Addr = std::net::Ipv4Addr::new(239, 255, 0, 1);

/// One line when this machine cannot join DDS discovery's multicast group on any interface the
/// participant may use (a container or network namespace with loopback only, an interface without
/// multicast): what it means for discovery, said once instead of RustDDS's per-message warnings.
/// `None` when a join succeeds, or when the scope does not look beyond this machine.
pub fn multicast_note(scope: &NetworkScope) -> Option<String> {
    use std::net::UdpSocket;
    let interfaces: Vec<Ipv4Addr> = match scope.participant_filter().0 {
        // No list: the kernel picks the interface from its routes, as for any multicast join.
        None => vec![Ipv4Addr::UNSPECIFIED],
        Some(list) => list
            .into_iter()
            .filter_map(|a| match a {
                IpAddr::V4(a) if !a.is_loopback() => Some(a),
                _ => None,
            })
            .collect(),
    };
    if interfaces.is_empty() {
        return None; // LOCALHOST or OFF: discovery is not meant to leave this machine
    }
    let socket = match UdpSocket::bind((Ipv4Addr::UNSPECIFIED, 0)) {
        Ok(s) => s,
        Err(e) => {
            return Some(format!(
                "DDS discovery: no UDP socket could be opened ({e})"
            ))
        }
    };
    let mut last_error = None;
    for interface in &interfaces {
        match socket.join_multicast_v4(&DISCOVERY_GROUP, interface) {
            Ok(()) => return None,
            Err(e) => last_error = Some(e),
        }
    }
    let why = last_error.map_or_else(String::new, |e| format!(": {e}"));
    Some(format!(
        "DDS discovery: no multicast on this machine (joining {DISCOVERY_GROUP}{why}): ROS 2 nodes \
         on other machines (edge cameras, the robot's driver) cannot discover this cell; nodes on this \
         machine still can, over loopback. Give the cell-network interface multicast \
         (docs/integrator.md, troubleshooting)."
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env(range: Option<&str>) -> ScopeEnv {
        ScopeEnv {
            automatic_discovery_range: range.map(str::to_owned),
            ..ScopeEnv::default()
        }
    }

    #[test]
    fn the_default_is_every_interface_and_the_config_pins_them() {
        let s = NetworkScope::resolve(None, None, &ScopeEnv::default()).unwrap();
        assert_eq!(s.participant_filter(), (None, true));
        let cell = [Ipv4Addr::new(10, 0, 5, 2)];
        let s = NetworkScope::resolve(None, Some(&cell), &env(Some("subnet"))).unwrap();
        assert_eq!(
            s.participant_filter(),
            (Some(vec![IpAddr::V4(cell[0])]), true)
        );
        assert_eq!(s.to_string(), "discovery range SUBNET on 10.0.5.2");
    }

    #[test]
    fn localhost_and_off_narrow_the_participant() {
        for (value, filter) in [
            (
                "LOCALHOST",
                (Some(vec![IpAddr::V4(Ipv4Addr::LOCALHOST)]), true),
            ),
            ("off", (Some(vec![]), false)),
            ("SYSTEM_DEFAULT", (None, true)),
            ("", (None, true)),
        ] {
            let s = NetworkScope::resolve(None, None, &env(Some(value))).unwrap();
            assert_eq!(s.participant_filter(), filter, "{value}");
        }
        let legacy = ScopeEnv {
            localhost_only: Some("1".to_owned()),
            ..ScopeEnv::default()
        };
        assert_eq!(
            NetworkScope::resolve(None, None, &legacy).unwrap().range,
            DiscoveryRange::Localhost
        );
    }

    #[test]
    fn contradictions_unknown_values_and_static_peers_are_refused() {
        let e = NetworkScope::resolve(Some(DiscoveryRange::Localhost), None, &env(Some("SUBNET")))
            .unwrap_err();
        assert!(e.to_string().contains("contradicts"), "{e}");
        assert_eq!(
            NetworkScope::resolve(
                Some(DiscoveryRange::Localhost),
                None,
                &env(Some("localhost"))
            )
            .unwrap()
            .range,
            DiscoveryRange::Localhost
        );
        assert!(NetworkScope::resolve(None, None, &env(Some("LAN"))).is_err());
        let peers = ScopeEnv {
            static_peers: Some("10.0.0.7".to_owned()),
            ..ScopeEnv::default()
        };
        let e = NetworkScope::resolve(None, None, &peers).unwrap_err();
        assert!(e.to_string().contains("not supported"), "{e}");
        assert!(NetworkScope::resolve(None, Some(&[]), &ScopeEnv::default()).is_err());
        assert!(
            NetworkScope::resolve(None, Some(&[Ipv4Addr::UNSPECIFIED]), &ScopeEnv::default())
                .is_err()
        );
    }
}

#[cfg(test)]
mod multicast_tests {
    use super::*;
    use std::net::Ipv4Addr;

    fn scope(range: DiscoveryRange, interfaces: Option<&[Ipv4Addr]>) -> NetworkScope {
        let env = ScopeEnv {
            automatic_discovery_range: None,
            static_peers: None,
            localhost_only: None,
        };
        NetworkScope::resolve(Some(range), interfaces, &env).expect("a valid scope")
    }

    #[test]
    fn multicast_note_only_where_discovery_should_leave_the_machine() {
        // An interface this machine does not have (TEST-NET-1, RFC 5737): no join can succeed.
        let absent = [Ipv4Addr::new(192, 0, 2, 1)];
        let note = multicast_note(&scope(DiscoveryRange::Subnet, Some(&absent)))
            .expect("a join on an absent interface fails");
        assert!(note.starts_with("DDS discovery: no multicast"), "{note}");
        assert!(
            note.contains("239.255.0.1") && !note.contains('\n'),
            "{note}"
        );
        // Discovery kept on this machine, or off: nothing to say.
        assert_eq!(
            multicast_note(&scope(DiscoveryRange::Localhost, None)),
            None
        );
        assert_eq!(multicast_note(&scope(DiscoveryRange::Off, None)), None);
    }
}
