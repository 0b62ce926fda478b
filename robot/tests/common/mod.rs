//! Shared fixtures: the shipped cell config, URDF and trajectory files.
#![allow(dead_code, clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

use ergocell_robot::signing::{self, PrivateKey, TrustedSigners};
use ergocell_robot::{
    CellConfig, InputHashes, RobotModel, TrajectoryClass, TrajectoryLayout, TrajectorySpec,
    TrustFiles,
};

pub fn repo_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A file by its path relative to the repository root.
pub fn read(rel: impl AsRef<Path>) -> String {
    let rel = rel.as_ref();
    std::fs::read_to_string(repo_root().join(rel))
        .unwrap_or_else(|e| panic!("{}: {e}", rel.display()))
}

/// The repository's trajectories folder, relative to its root (read with [`read`]).
pub fn layout() -> TrajectoryLayout {
    TrajectoryLayout::default()
}

pub struct Shipped {
    pub cell_text: String,
    pub cell: CellConfig,
    pub urdf: String,
    pub model: RobotModel,
}

pub fn shipped() -> Shipped {
    let cell_text = read("config/cell.toml");
    let cell = CellConfig::from_toml_str(&cell_text).unwrap();
    let urdf = read(format!("config/{}", cell.robot.urdf));
    let model =
        RobotModel::from_urdf_str(&urdf, &cell.robot.base_link, &cell.robot.flange_link).unwrap();
    Shipped {
        cell_text,
        cell,
        urdf,
        model,
    }
}

pub fn spec_text(class: TrajectoryClass) -> String {
    read(layout().spec(class))
}

/// The tests' approvers: two trusted engineers and one outsider, keys from fixed seeds.
pub struct Approvers {
    pub alice: PrivateKey,
    pub bob: PrivateKey,
    pub mallory: PrivateKey,
    /// allowed_signers naming alice@plant.example and bob@plant.example.
    pub allowed_signers: String,
    /// An empty revocation list.
    pub revoked_keys: String,
    pub trusted: TrustedSigners,
}

pub const ALICE: &str = "alice@plant.example";
pub const BOB: &str = "bob@plant.example";

/// One allowed-signers line for `key` as `principal`.
pub fn allowed_line(principal: &str, key: &PrivateKey) -> String {
    format!(
        "{principal} namespaces=\"{}\" {}\n",
        signing::APPROVAL_NAMESPACE,
        signing::public_key_openssh(key).unwrap()
    )
}

pub fn signers() -> Approvers {
    let alice = signing::key_from_seed(&[1; 32], "alice");
    let bob = signing::key_from_seed(&[2; 32], "bob");
    let mallory = signing::key_from_seed(&[3; 32], "mallory");
    let allowed_signers = format!(
        "# test approvers\n{}{}",
        allowed_line(ALICE, &alice),
        allowed_line(BOB, &bob)
    );
    let revoked_keys = String::new();
    let trusted = TrustedSigners::parse(&allowed_signers, &revoked_keys).unwrap();
    Approvers {
        alice,
        bob,
        mallory,
        allowed_signers,
        revoked_keys,
        trusted,
    }
}

/// The current hashes of the shipped cell with `spec_text` and the test approvers' files.
pub fn hashes(s: &Shipped, spec_text: &str) -> InputHashes {
    hashes_with_trust(s, spec_text, &signers())
}

pub fn hashes_with_trust(s: &Shipped, spec_text: &str, t: &Approvers) -> InputHashes {
    InputHashes::new(
        spec_text.as_bytes(),
        s.urdf.as_bytes(),
        &s.cell,
        TrustFiles {
            allowed_signers: t.allowed_signers.as_bytes(),
            revoked_keys: t.revoked_keys.as_bytes(),
        },
        "test",
    )
}

/// The shipped approvers' files' bytes.
pub fn shipped_trust() -> (String, String) {
    (
        read(format!("config/{}", signing::ALLOWED_SIGNERS)),
        read(format!("config/{}", signing::REVOKED_KEYS)),
    )
}

pub fn spec(class: TrajectoryClass) -> TrajectorySpec {
    TrajectorySpec::from_toml_str(&spec_text(class)).unwrap()
}
