//! `ergocell security`: DDS Security (SROS2) for the cell.
//!
//! ```text
//! ergocell security create-keystore --keystore DIR [--config config/cell.toml] [--days 365]
//! ```
//!
//! writes what `ros2 security create_keystore` and `create_enclave` would, for every node of the cell
//! with least-privilege permissions from `[ros]` (`ergocell_bridge::security`). `DIR` must not exist
//! (nothing is overwritten); private keys are written readable by their owner only. `run` and
//! `replay --ros` then take `--keystore DIR` (or `ROS_SECURITY_KEYSTORE`, or `[ros] keystore`).

use std::path::{Path, PathBuf};

use anyhow::Context as _;
use ergocell_bridge::security::{cell_enclaves, create_keystore};
use ergocell_bridge::transport::RosConfig;

use super::UsageError;

/// Arguments of `ergocell security`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: Sub,
}

#[derive(Debug, clap::Subcommand)]
pub enum Sub {
    /// Create an SROS2 keystore: identity and permissions CAs, a signed governance, and one enclave per
    /// node of the cell (cell, each camera, replay, recorder, the robot's controller).
    CreateKeystore {
        /// The keystore folder to create (must not exist).
        #[arg(long)]
        keystore: PathBuf,
        /// Cell configuration (its `[ros]` table: domain, cameras, topics).
        #[arg(long, default_value = "config/cell.toml")]
        config: PathBuf,
        /// Validity of the certificates and permissions, days from now (1..=3650).
        #[arg(long, default_value_t = 365)]
        days: u32,
    },
}

/// Seconds since the Unix epoch (the binary's clock boundary), an hour back for clock skew.
#[allow(clippy::disallowed_methods)]
fn not_before() -> i64 {
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(0));
    now - 3600
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    match &args.command {
        Sub::CreateKeystore {
            keystore,
            config,
            days,
        } => create(keystore, config, *days),
    }
}

fn create(keystore: &Path, config: &Path, days: u32) -> anyhow::Result<()> {
    if !(1..=3650).contains(&days) {
        return Err(UsageError(format!("--days {days}: expected 1..=3650")).into());
    }
    if keystore.exists() {
        return Err(UsageError(format!(
            "{} exists: a keystore is created in a new folder (nothing is overwritten)",
            keystore.display()
        ))
        .into());
    }
    let (text, label) = ergocell::shipped::read_or_shipped(config)?;
    let ros = RosConfig::from_cell_toml(&text).map_err(|e| UsageError(format!("{label}: {e}")))?;
    let enclaves = cell_enclaves(&ros);
    let files = create_keystore(ros.domain_id, &enclaves, not_before(), days)?;
    for f in &files {
        let path = keystore.join(&f.path);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)
                .with_context(|| format!("cannot create {}", dir.display()))?;
        }
        write_new(&path, &f.contents, f.secret)?;
    }
    println!(
        "created SROS2 keystore {} for DDS domain {}, valid {days} days:",
        keystore.display(),
        ros.domain_id
    );
    for e in &enclaves {
        println!(
            "  enclave {:<28} publishes {}, subscribes {}",
            e.name,
            list(&e.publish),
            list(&e.subscribe)
        );
    }
    println!(
        "keep {}/private/ (the CA keys) off the cell; copy each node's enclaves/<name>/ to where it runs",
        keystore.display()
    );
    Ok(())
}

fn list(topics: &[String]) -> String {
    if topics.is_empty() {
        "nothing".to_owned()
    } else {
        topics.join(" ")
    }
}

/// Writes a new file (never overwrites); a secret one readable by its owner only.
fn write_new(path: &Path, contents: &[u8], secret: bool) -> anyhow::Result<()> {
    use std::io::Write as _;
    let mut options = std::fs::OpenOptions::new();
    options.write(true).create_new(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.mode(if secret { 0o600 } else { 0o644 });
    }
    let mut f = options
        .open(path)
        .with_context(|| format!("cannot create {}", path.display()))?;
    f.write_all(contents)
        .with_context(|| format!("cannot write {}", path.display()))
}
