//! DDS Security (SROS2) for the cell: the keystore `ros2 security` would make, with least-privilege
//! permissions derived from the cell's own topics.
//!
//! Layout (the SROS2 conventions, so ROS 2 tools and peers read it):
//! - `public/identity_ca.cert.pem`, `public/permissions_ca.cert.pem`: two self-signed ECDSA P-256 CAs,
//!   one that vouches for who a participant is, one that signs what it may do;
//!   `private/identity_ca.key.pem`, `private/permissions_ca.key.pem`: their keys (keep them off the cell).
//! - `enclaves/governance.xml` and `governance.p7s` (S/MIME, signed by the permissions CA): every
//!   participant authenticated (PKI-DH), join and read/write access controlled, discovery, liveliness
//!   and data encrypted (AES-GCM), RTPS messages signed.
//! - `enclaves/<enclave>/`: `cert.pem` and `key.pem` (the participant's identity, `CN=<enclave>`,
//!   issued by the identity CA), both CA certificates, `governance.p7s`, and `permissions.xml` /
//!   `permissions.p7s`: what this enclave may publish and subscribe, default DENY — the file names
//!   RustDDS (`DomainParticipantSecurityConfigFiles::with_ros_default_names`) and rmw implementations read.
//!
//! Enclaves ([`cell_enclaves`]): `/ergocell/cell` (the controller: subscribes the cameras and
//! `/joint_states`, publishes the trajectory and the session topics), one `/ergocell/camera/<id>` per
//! camera (publishes its own landmarks topic only), `/ergocell/replay` (the replay tool: publishes the
//! camera topics, as the cameras would), `/ergocell/recorder` (subscribes only) and `/robot/controller`
//! (the robot's controller: publishes `/joint_states`, subscribes the trajectory).
//!
//! The cryptography is OpenSSL's (the `openssl` crate, which RustDDS's security already links); this
//! module writes nothing to disk: it returns the files for the binary to write.

use std::fmt::Write as _;

use openssl::asn1::{Asn1Integer, Asn1Time};
use openssl::bn::BigNum;
use openssl::ec::{EcGroup, EcKey};
use openssl::hash::MessageDigest;
use openssl::nid::Nid;
use openssl::pkcs7::{Pkcs7, Pkcs7Flags};
use openssl::pkey::{PKey, Private};
use openssl::stack::Stack;
use openssl::x509::extension::{BasicConstraints, KeyUsage};
use openssl::x509::{X509Builder, X509NameBuilder, X509};

use crate::transport::RosConfig;
use crate::BridgeError;

/// One participant identity and what it may do, by ROS topic name (`/joint_states`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EnclaveSpec {
    /// The enclave's name, a ROS path (`/ergocell/cell`); also its certificate's `CN`.
    pub name: String,
    pub publish: Vec<String>,
    pub subscribe: Vec<String>,
}

/// The cell's enclaves, least privilege, from `[ros]` (topics and cameras).
pub fn cell_enclaves(ros: &RosConfig) -> Vec<EnclaveSpec> {
    let cameras: Vec<String> = ros.cameras.iter().map(|c| ros.camera_topic_of(c)).collect();
    let session = vec![
        ros.session_state_topic.clone(),
        ros.session_events_topic.clone(),
        ros.ergonomics_topic.clone(),
        ros.reba_topic.clone(),
        ros.warnings_topic.clone(),
        ros.skeleton_topic.clone(),
        ros.controller_events_topic.clone(),
    ];
    let mut out = vec![EnclaveSpec {
        name: "/ergocell/cell".to_owned(),
        publish: [vec![ros.joint_trajectory_topic.clone()], session.clone()].concat(),
        subscribe: [
            cameras.clone(),
            vec![
                ros.joint_states_topic.clone(),
                ros.is_configured_topic.clone(),
                ros.hardware_event_topic.clone(),
            ],
        ]
        .concat(),
    }];
    for (id, topic) in ros.cameras.iter().zip(&cameras) {
        out.push(EnclaveSpec {
            name: format!("/ergocell/camera/{id}"),
            publish: vec![topic.clone()],
            subscribe: Vec::new(),
        });
    }
    out.push(EnclaveSpec {
        name: "/ergocell/replay".to_owned(),
        publish: cameras.clone(),
        subscribe: Vec::new(),
    });
    out.push(EnclaveSpec {
        name: "/ergocell/recorder".to_owned(),
        publish: Vec::new(),
        subscribe: [
            session,
            cameras,
            vec![
                ros.joint_states_topic.clone(),
                ros.joint_trajectory_topic.clone(),
            ],
        ]
        .concat(),
    });
    out.push(EnclaveSpec {
        name: "/robot/controller".to_owned(),
        publish: vec![
            ros.joint_states_topic.clone(),
            ros.is_configured_topic.clone(),
            ros.hardware_event_topic.clone(),
        ],
        subscribe: vec![
            ros.joint_trajectory_topic.clone(),
            ros.session_state_topic.clone(),
        ],
    });
    out
}

/// A file of the keystore, relative to its root.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KeystoreFile {
    pub path: String,
    pub contents: Vec<u8>,
    /// A private key: write it readable by the owner only.
    pub secret: bool,
}

/// The DDS topic of a ROS topic (`/joint_states` → `rt/joint_states`).
pub fn dds_topic(ros_topic: &str) -> String {
    format!("rt/{}", ros_topic.trim_start_matches('/'))
}

fn err(what: &str) -> impl Fn(openssl::error::ErrorStack) -> BridgeError + '_ {
    move |e| BridgeError::Config(format!("{what}: {e}"))
}

fn new_key() -> Result<PKey<Private>, BridgeError> {
    let group = EcGroup::from_curve_name(Nid::X9_62_PRIME256V1).map_err(err("EC group"))?;
    let key = EcKey::generate(&group).map_err(err("EC key"))?;
    PKey::from_ec_key(key).map_err(err("EC key"))
}

/// A certificate for `cn` with `key`, issued by (`issuer`, `issuer_key`) or self-signed.
fn certificate(
    cn: &str,
    key: &PKey<Private>,
    issuer: Option<(&X509, &PKey<Private>)>,
    ca: bool,
    serial: u32,
    not_before_unix: i64,
    days: u32,
) -> Result<X509, BridgeError> {
    let e = err("certificate");
    let mut name = X509NameBuilder::new().map_err(&e)?;
    name.append_entry_by_nid(Nid::COMMONNAME, cn).map_err(&e)?;
    let name = name.build();
    let mut b = X509Builder::new().map_err(&e)?;
    b.set_version(2).map_err(&e)?;
    let serial = BigNum::from_u32(serial).map_err(&e)?;
    let serial = Asn1Integer::from_bn(&serial).map_err(&e)?;
    b.set_serial_number(&serial).map_err(&e)?;
    b.set_subject_name(&name).map_err(&e)?;
    match issuer {
        Some((cert, _)) => b.set_issuer_name(cert.subject_name()).map_err(&e)?,
        None => b.set_issuer_name(&name).map_err(&e)?,
    }
    b.set_pubkey(key).map_err(&e)?;
    let not_before = Asn1Time::from_unix(not_before_unix).map_err(&e)?;
    b.set_not_before(&not_before).map_err(&e)?;
    let not_after = Asn1Time::from_unix(not_before_unix + i64::from(days) * 86_400).map_err(&e)?;
    b.set_not_after(&not_after).map_err(&e)?;
    if ca {
        b.append_extension(
            BasicConstraints::new()
                .critical()
                .ca()
                .pathlen(1)
                .build()
                .map_err(&e)?,
        )
        .map_err(&e)?;
        b.append_extension(
            // digitalSignature too: the permissions CA signs the governance and permissions
            // documents itself, and OpenSSL's S/MIME verification (Cyclone DDS's) checks it.
            KeyUsage::new()
                .critical()
                .key_cert_sign()
                .crl_sign()
                .digital_signature()
                .build()
                .map_err(&e)?,
        )
        .map_err(&e)?;
    } else {
        b.append_extension(BasicConstraints::new().build().map_err(&e)?)
            .map_err(&e)?;
        b.append_extension(
            KeyUsage::new()
                .critical()
                .digital_signature()
                .key_agreement()
                .build()
                .map_err(&e)?,
        )
        .map_err(&e)?;
    }
    let signer = issuer.map_or(key, |(_, k)| k);
    b.sign(signer, MessageDigest::sha256()).map_err(&e)?;
    Ok(b.build())
}

/// `document` signed by (`cert`, `key`) as S/MIME multipart/signed with the text flag, exactly what
/// `openssl smime -sign -text` writes (and SROS2 and RustDDS read).
pub fn smime_sign(
    document: &[u8],
    cert: &X509,
    key: &PKey<Private>,
) -> Result<Vec<u8>, BridgeError> {
    let e = err("S/MIME signature");
    let flags = Pkcs7Flags::DETACHED | Pkcs7Flags::TEXT;
    let certs = Stack::new().map_err(&e)?;
    let p7 = Pkcs7::sign(cert, key, &certs, document, flags).map_err(&e)?;
    p7.to_smime(document, flags).map_err(&e)
}

fn iso(unix: i64) -> Result<String, BridgeError> {
    let t = time::OffsetDateTime::from_unix_timestamp(unix)
        .map_err(|e| BridgeError::Config(format!("time {unix}: {e}")))?;
    Ok(format!(
        "{:04}-{:02}-{:02}T{:02}:{:02}:{:02}",
        t.year(),
        u8::from(t.month()),
        t.day(),
        t.hour(),
        t.minute(),
        t.second()
    ))
}

/// The governance document: authenticated participants only, everything encrypted and access
/// controlled on `domain_id`.
pub fn governance_xml(domain_id: u16) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains>
        <id>{domain_id}</id>
      </domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>SIGN</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
"#
    )
}

fn topics_xml(out: &mut String, tag: &str, topics: &[String]) {
    if topics.is_empty() {
        return;
    }
    let _ = writeln!(out, "        <{tag}>\n          <topics>");
    for t in topics {
        let _ = writeln!(out, "            <topic>{t}</topic>");
    }
    let _ = writeln!(out, "          </topics>\n        </{tag}>");
}

/// The permissions document of one enclave (default DENY). ROS 2's own bookkeeping topics
/// (`ros_discovery_info`, `rt/parameter_events`, publishing `rt/rosout`, reading `rt/clock`) are
/// allowed besides the enclave's topics; ergocell's nodes run no parameter services.
pub fn permissions_xml(
    domain_id: u16,
    enclave: &EnclaveSpec,
    not_before_unix: i64,
    days: u32,
) -> Result<String, BridgeError> {
    let mut publish: Vec<String> = enclave.publish.iter().map(|t| dds_topic(t)).collect();
    let mut subscribe: Vec<String> = enclave.subscribe.iter().map(|t| dds_topic(t)).collect();
    for list in [&mut publish, &mut subscribe] {
        list.push("ros_discovery_info".to_owned());
        list.push("rt/parameter_events".to_owned());
    }
    // Every ROS 2 context creates the log topic (ergocell's nodes log nothing to it), and every node
    // reads the ROS clock.
    publish.push("rt/rosout".to_owned());
    subscribe.push("rt/clock".to_owned());
    let mut out = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">
  <permissions>
    <grant name="{name}">
      <subject_name>CN={name}</subject_name>
      <validity>
        <not_before>{nb}</not_before>
        <not_after>{na}</not_after>
      </validity>
      <allow_rule>
        <domains>
          <id>{domain_id}</id>
        </domains>
"#,
        name = enclave.name,
        nb = iso(not_before_unix)?,
        na = iso(not_before_unix + i64::from(days) * 86_400)?,
    );
    topics_xml(&mut out, "publish", &publish);
    topics_xml(&mut out, "subscribe", &subscribe);
    out.push_str("      </allow_rule>\n      <default>DENY</default>\n    </grant>\n  </permissions>\n</dds>\n");
    Ok(out)
}

fn check_name(name: &str) -> Result<(), BridgeError> {
    let ok = name.starts_with('/')
        && name.len() > 1
        && name[1..]
            .split('/')
            .all(|p| !p.is_empty() && p.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'));
    if ok {
        Ok(())
    } else {
        Err(BridgeError::Config(format!(
            "enclave name `{name}`: expected a ROS path like /ergocell/cell (letters, digits, _)"
        )))
    }
}

/// Every file of a new keystore for `enclaves` on `domain_id`, valid from `not_before_unix` for
/// `days` days. Fresh keys each call.
pub fn create_keystore(
    domain_id: u16,
    enclaves: &[EnclaveSpec],
    not_before_unix: i64,
    days: u32,
) -> Result<Vec<KeystoreFile>, BridgeError> {
    let pem = |r: Result<Vec<u8>, openssl::error::ErrorStack>| r.map_err(err("PEM"));
    let id_key = new_key()?;
    let id_ca = certificate(
        "ergocell identity CA",
        &id_key,
        None,
        true,
        1,
        not_before_unix,
        days,
    )?;
    let perm_key = new_key()?;
    let perm_ca = certificate(
        "ergocell permissions CA",
        &perm_key,
        None,
        true,
        1,
        not_before_unix,
        days,
    )?;
    let id_pem = pem(id_ca.to_pem())?;
    let perm_pem = pem(perm_ca.to_pem())?;
    let governance = governance_xml(domain_id);
    let governance_p7s = smime_sign(governance.as_bytes(), &perm_ca, &perm_key)?;
    let file = |path: String, contents: Vec<u8>, secret: bool| KeystoreFile {
        path,
        contents,
        secret,
    };
    let mut files = vec![
        file("public/identity_ca.cert.pem".into(), id_pem.clone(), false),
        file(
            "public/permissions_ca.cert.pem".into(),
            perm_pem.clone(),
            false,
        ),
        file(
            "private/identity_ca.key.pem".into(),
            pem(id_key.private_key_to_pem_pkcs8())?,
            true,
        ),
        file(
            "private/permissions_ca.key.pem".into(),
            pem(perm_key.private_key_to_pem_pkcs8())?,
            true,
        ),
        file(
            "enclaves/governance.xml".into(),
            governance.into_bytes(),
            false,
        ),
        file(
            "enclaves/governance.p7s".into(),
            governance_p7s.clone(),
            false,
        ),
    ];
    for (k, enclave) in enclaves.iter().enumerate() {
        check_name(&enclave.name)?;
        let dir = format!("enclaves{}", enclave.name);
        let key = new_key()?;
        let serial = u32::try_from(k + 2).unwrap_or(u32::MAX);
        let cert = certificate(
            &enclave.name,
            &key,
            Some((&id_ca, &id_key)),
            false,
            serial,
            not_before_unix,
            days,
        )?;
        let permissions = permissions_xml(domain_id, enclave, not_before_unix, days)?;
        let permissions_p7s = smime_sign(permissions.as_bytes(), &perm_ca, &perm_key)?;
        files.extend([
            file(format!("{dir}/cert.pem"), pem(cert.to_pem())?, false),
            file(
                format!("{dir}/key.pem"),
                pem(key.private_key_to_pem_pkcs8())?,
                true,
            ),
            file(format!("{dir}/identity_ca.cert.pem"), id_pem.clone(), false),
            file(
                format!("{dir}/permissions_ca.cert.pem"),
                perm_pem.clone(),
                false,
            ),
            file(
                format!("{dir}/governance.p7s"),
                governance_p7s.clone(),
                false,
            ),
            file(
                format!("{dir}/permissions.xml"),
                permissions.into_bytes(),
                false,
            ),
            file(format!("{dir}/permissions.p7s"), permissions_p7s, false),
        ]);
    }
    Ok(files)
}

/// What the process said about DDS Security (ROS 2's variables), as the binary read it.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SecurityEnv {
    /// `ROS_SECURITY_ENABLE` (`true` / `false`).
    pub enable: Option<String>,
    /// `ROS_SECURITY_STRATEGY` (`Enforce`, the default, or `Permissive`).
    pub strategy: Option<String>,
    /// `ROS_SECURITY_KEYSTORE`.
    pub keystore: Option<String>,
    /// `ROS_SECURITY_ENCLAVE_OVERRIDE` (an enclave name, `/ergocell/cell`).
    pub enclave_override: Option<String>,
}

/// The participant's security, decided.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SecurityDecision {
    /// No DDS Security (with why, for the log).
    Off(String),
    /// DDS Security with this enclave.
    Enclave {
        name: String,
        dir: std::path::PathBuf,
    },
}

/// Decides whether and with which enclave the participant runs secured.
///
/// The keystore is `cli_keystore`, else `ROS_SECURITY_KEYSTORE`, else `config_keystore`; security is on
/// when `ROS_SECURITY_ENABLE=true`, when a keystore is given on the command line or in the config, or
/// when `required` (`[ros] security_required`). The enclave is `ROS_SECURITY_ENCLAVE_OVERRIDE`, else
/// `default_enclave`. Under `Permissive` a missing enclave runs unsecured (said in the log), unless
/// security is required; under `Enforce` it is an error. `enclave_exists` tells whether the enclave
/// folder holds the files (the caller looks; this function does no I/O).
pub fn resolve_security(
    required: bool,
    config_keystore: Option<&std::path::Path>,
    cli_keystore: Option<&std::path::Path>,
    default_enclave: &str,
    env: &SecurityEnv,
    enclave_exists: impl Fn(&std::path::Path) -> bool,
) -> Result<SecurityDecision, BridgeError> {
    let env_enable = match env
        .enable
        .as_deref()
        .map(|v| v.trim().to_ascii_lowercase())
        .as_deref()
    {
        None | Some("") => None,
        Some("true") => Some(true),
        Some("false") => Some(false),
        Some(other) => {
            return Err(BridgeError::Config(format!(
                "ROS_SECURITY_ENABLE={other}: expected true or false"
            )))
        }
    };
    let permissive = match env
        .strategy
        .as_deref()
        .map(|v| v.trim().to_ascii_lowercase())
        .as_deref()
    {
        None | Some("" | "enforce") => false,
        Some("permissive") => true,
        Some(other) => {
            return Err(BridgeError::Config(format!(
                "ROS_SECURITY_STRATEGY={other}: expected Enforce or Permissive"
            )))
        }
    };
    if required && env_enable == Some(false) {
        return Err(BridgeError::Config(
            "ROS_SECURITY_ENABLE=false, but the cell config requires DDS Security ([ros] security_required = true)"
                .to_owned(),
        ));
    }
    let env_keystore = env
        .keystore
        .as_deref()
        .filter(|k| !k.trim().is_empty())
        .map(std::path::PathBuf::from);
    let keystore = cli_keystore
        .map(std::path::Path::to_path_buf)
        .or(env_keystore)
        .or_else(|| config_keystore.map(std::path::Path::to_path_buf));
    let on = required
        || env_enable == Some(true)
        || cli_keystore.is_some()
        || (env_enable.is_none() && config_keystore.is_some());
    if !on {
        return Ok(SecurityDecision::Off(
            "DDS Security off (no keystore given; [ros] security_required is false)".to_owned(),
        ));
    }
    let Some(keystore) = keystore else {
        return Err(BridgeError::Config(if required {
            "the cell config requires DDS Security ([ros] security_required = true): give --keystore, \
             ROS_SECURITY_KEYSTORE or [ros] keystore (create one with `ergocell security create-keystore`)"
                .to_owned()
        } else {
            "ROS_SECURITY_ENABLE=true but no keystore: give --keystore or ROS_SECURITY_KEYSTORE"
                .to_owned()
        }));
    };
    let name = env
        .enclave_override
        .as_deref()
        .filter(|n| !n.trim().is_empty())
        .unwrap_or(default_enclave)
        .to_owned();
    check_name(&name)?;
    let dir = keystore.join("enclaves").join(name.trim_start_matches('/'));
    if !enclave_exists(&dir) {
        if permissive && !required {
            return Ok(SecurityDecision::Off(format!(
                "DDS Security off: no enclave {name} in {} and ROS_SECURITY_STRATEGY=Permissive",
                keystore.display()
            )));
        }
        return Err(BridgeError::Config(format!(
            "no SROS2 enclave {name} in keystore {} (expected {})",
            keystore.display(),
            dir.display()
        )));
    }
    Ok(SecurityDecision::Enclave { name, dir })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    fn env(enable: Option<&str>, keystore: Option<&str>) -> SecurityEnv {
        SecurityEnv {
            enable: enable.map(str::to_owned),
            keystore: keystore.map(str::to_owned),
            ..SecurityEnv::default()
        }
    }

    #[test]
    fn security_is_off_by_default_and_required_means_required() {
        let yes = |_: &Path| true;
        let no = |_: &Path| false;
        assert!(matches!(
            resolve_security(
                false,
                None,
                None,
                "/ergocell/cell",
                &SecurityEnv::default(),
                yes
            )
            .unwrap(),
            SecurityDecision::Off(_)
        ));
        let e = resolve_security(
            true,
            None,
            None,
            "/ergocell/cell",
            &SecurityEnv::default(),
            yes,
        )
        .unwrap_err();
        assert!(e.to_string().contains("requires DDS Security"), "{e}");
        let e = resolve_security(
            true,
            None,
            None,
            "/ergocell/cell",
            &env(Some("false"), Some("/k")),
            yes,
        )
        .unwrap_err();
        assert!(e.to_string().contains("ROS_SECURITY_ENABLE=false"), "{e}");
        // The environment's keystore and the default enclave.
        let d = resolve_security(
            false,
            None,
            None,
            "/ergocell/cell",
            &env(Some("true"), Some("/k")),
            yes,
        )
        .unwrap();
        assert_eq!(
            d,
            SecurityDecision::Enclave {
                name: "/ergocell/cell".to_owned(),
                dir: Path::new("/k/enclaves/ergocell/cell").to_path_buf()
            }
        );
        // Missing enclave: Enforce refuses; Permissive runs unsecured unless required.
        assert!(resolve_security(
            false,
            None,
            Some(Path::new("/k")),
            "/ergocell/cell",
            &SecurityEnv::default(),
            no
        )
        .is_err());
        let permissive = SecurityEnv {
            strategy: Some("Permissive".to_owned()),
            enable: Some("true".to_owned()),
            keystore: Some("/k".to_owned()),
            ..SecurityEnv::default()
        };
        assert!(matches!(
            resolve_security(false, None, None, "/ergocell/cell", &permissive, no).unwrap(),
            SecurityDecision::Off(_)
        ));
        assert!(resolve_security(true, None, None, "/ergocell/cell", &permissive, no).is_err());
        // The override names another enclave; a bad name is refused.
        let over = SecurityEnv {
            enclave_override: Some("/ergocell/camera/s1_left".to_owned()),
            ..env(Some("true"), Some("/k"))
        };
        assert!(matches!(
            resolve_security(false, None, None, "/ergocell/cell", &over, yes).unwrap(),
            SecurityDecision::Enclave { name, .. } if name == "/ergocell/camera/s1_left"
        ));
        let bad = SecurityEnv {
            enclave_override: Some("../../etc".to_owned()),
            ..env(Some("true"), Some("/k"))
        };
        assert!(resolve_security(false, None, None, "/ergocell/cell", &bad, yes).is_err());
    }

    #[test]
    fn permissions_list_only_the_enclaves_topics_plus_ros_bookkeeping() {
        let e = EnclaveSpec {
            name: "/ergocell/camera/s1_left".to_owned(),
            publish: vec!["/ergocell/camera/s1_left/landmarks".to_owned()],
            subscribe: vec![],
        };
        let xml = permissions_xml(3, &e, 0, 1).unwrap();
        assert!(xml.contains("<subject_name>CN=/ergocell/camera/s1_left</subject_name>"));
        assert!(xml.contains("<topic>rt/ergocell/camera/s1_left/landmarks</topic>"));
        assert!(xml.contains("<id>3</id>") && xml.contains("<default>DENY</default>"));
        assert!(xml.contains("<not_before>1970-01-01T00:00:00</not_before>"));
        assert!(!xml.contains("joint"));
        assert_eq!(dds_topic("/joint_states"), "rt/joint_states");
    }
}
