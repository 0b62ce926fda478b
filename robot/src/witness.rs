//! The witness: what the cell has seen of each approvals file, so that a rollback is caught.
//!
//! An approvals file is a hash chain ([`crate::lock`]): an edited or removed entry *inside* it breaks
//! the chain, and a lock file older than the chain's last approval is refused as superseded. What
//! the chain alone cannot show is a file cut back at an entry boundary — the last entry deleted (a
//! withdrawal undone, say), or lock and approvals restored together from an older copy — because the
//! older chain is valid in itself. Catching that needs a memory kept apart from the files: this
//! witness, an append-only log of *sightings* ("the approvals file at this path had N entries whose
//! last hashed to H"). Every later reading must **extend** every sighting: at least N entries, and
//! entry N − 1 hashing to H. This is the version check The Update Framework uses against rollback
//! attacks (TUF specification, "rollback attack"): the verifier remembers the newest version it has
//! trusted and refuses anything older.
//!
//! The log is JSON Lines, one [`Sighting`] per line, only ever appended to. Where it lives, and so
//! who can delete it, is the binary's choice; a witness its attacker can delete catches careless
//! rollbacks only, one on an append-only file (`chattr +a`) in a folder the cell's account cannot
//! write catches hostile ones too. This module parses the text, checks a chain against it and
//! writes the next line; it does no I/O.

use serde::{Deserialize, Serialize};

use crate::config::TrajectoryClass;
use crate::lock::ApprovalsFile;
use crate::signing::{self, TrustedSigners};
use crate::RobotError;

/// Format tag of each witness line.
pub const WITNESS_FORMAT: &str = "ergocell-witness/1";

/// One line of the witness: an approvals file as it was seen.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sighting {
    pub format: String,
    /// Which approvals file (the binary's absolute path of it).
    pub approvals: String,
    pub class: TrajectoryClass,
    /// How many entries the chain had.
    pub entries: usize,
    /// The SHA-256 of its last entry ([`crate::lock::Approval::entry_sha256`]).
    pub head_sha256: String,
    /// When it was seen (RFC 3339 UTC).
    pub seen_at_utc: String,
}

/// A parsed witness log: its sightings, and the lines that could not be read.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Witness {
    /// `(line number from 1, sighting)`.
    sightings: Vec<(usize, Sighting)>,
    /// Lines passed over, with why: a damaged line is named, never fatal (the log only ever adds
    /// what the chain must extend; losing a line can only make the check weaker, never refuse).
    pub unreadable: Vec<String>,
}

impl Witness {
    /// Parses a witness log. A last line without its newline is an append cut short (a crash while
    /// writing) and is passed over like any line that does not parse; both are listed in
    /// [`Witness::unreadable`].
    pub fn parse(text: &str) -> Self {
        let mut witness = Self::default();
        let complete = text.ends_with('\n');
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            let number = i + 1;
            if line.trim().is_empty() {
                continue;
            }
            if i + 1 == lines.len() && !complete {
                witness
                    .unreadable
                    .push(format!("line {number}: cut short (no newline)"));
                continue;
            }
            match serde_json::from_str::<Sighting>(line) {
                Ok(s) if s.format == WITNESS_FORMAT && signing::is_sha256_hex(&s.head_sha256) => {
                    witness.sightings.push((number, s));
                }
                Ok(s) if s.format != WITNESS_FORMAT => witness.unreadable.push(format!(
                    "line {number}: format `{}`, not `{WITNESS_FORMAT}`",
                    signing::printable(&s.format)
                )),
                Ok(_) => witness
                    .unreadable
                    .push(format!("line {number}: head_sha256 is not a SHA-256")),
                Err(e) => witness.unreadable.push(format!(
                    "line {number}: {}",
                    signing::printable(&e.to_string())
                )),
            }
        }
        witness
    }

    /// The sightings of one approvals file and class.
    fn of<'a>(
        &'a self,
        approvals: &'a str,
        class: TrajectoryClass,
    ) -> impl Iterator<Item = &'a (usize, Sighting)> + 'a {
        self.sightings
            .iter()
            .filter(move |(_, s)| s.approvals == approvals && s.class == class)
    }

    /// Checks that `file` (the approvals file at `approvals`, its chain already checked) extends
    /// every sighting of it: no entry the cell has seen is gone or different.
    pub fn check(
        &self,
        approvals: &str,
        class: TrajectoryClass,
        file: &ApprovalsFile,
    ) -> Result<(), RobotError> {
        for (line, seen) in self.of(approvals, class) {
            let now = file.approval.len();
            let kept = seen.entries == 0
                || file
                    .approval
                    .get(seen.entries - 1)
                    .is_some_and(|e| e.entry_sha256() == seen.head_sha256);
            if !kept {
                let at = signing::printable(&seen.seen_at_utc);
                return Err(RobotError::RolledBack {
                    class: class.to_string(),
                    what: if now < seen.entries {
                        format!("has {now} entries, but on {at} it had {}", seen.entries)
                    } else {
                        format!(
                            "has {now} entries, but its first {} are not those seen on {at}",
                            seen.entries
                        )
                    },
                    witness_line: *line,
                });
            }
        }
        Ok(())
    }

    /// The line to append after `file` passed [`Witness::check`], if a trusted approver vouches for
    /// more of it than any sighting holds (`None` when the witness already knows this much).
    ///
    /// Only what a trusted signature covers is recorded: the chain up to its last entry whose
    /// signature `trusted` accepts (that entry's `previous_sha256` commits to everything before it).
    /// An entry no trusted key signed (a forgery appended to the file) is never witnessed, so
    /// removing it later is not a rollback.
    pub fn sighting_line(
        &self,
        approvals: &str,
        class: TrajectoryClass,
        file: &ApprovalsFile,
        trusted: &TrustedSigners,
        now_utc: &str,
    ) -> Option<String> {
        let known = self
            .of(approvals, class)
            .map(|(_, s)| s.entries)
            .max()
            .unwrap_or(0);
        let vouched = file
            .approval
            .iter()
            .rposition(|e| trusted.verify(&e.claim(), &e.signature).is_ok())?;
        if vouched < known {
            return None;
        }
        let sighting = Sighting {
            format: WITNESS_FORMAT.to_owned(),
            approvals: approvals.to_owned(),
            class,
            entries: vouched + 1,
            head_sha256: file.approval[vouched].entry_sha256(),
            seen_at_utc: now_utc.to_owned(),
        };
        serde_json::to_string(&sighting).ok().map(|l| l + "\n")
    }
}
