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

/// A parsed witness log: its sightings, and what was passed over.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Witness {
    /// `(line number from 1, sighting)`.
    sightings: Vec<(usize, Sighting)>,
    /// What was passed over, with why: only an append a crash cut short (the last line without its
    /// newline, or such a fragment before the next whole line). Any other line that is not a
    /// sighting makes the whole witness unreadable ([`RobotError::WitnessUnreadable`]): a witness
    /// its attacker can switch off by appending one bad byte witnesses nothing.
    pub unreadable: Vec<String>,
}

/// The start of every line ergocell writes (`Sighting`'s first field).
const LINE_START: &[u8] = b"{\"format\":";

/// One line as a sighting, or why it is not one.
fn sighting(line: &[u8]) -> Result<Sighting, String> {
    let text = std::str::from_utf8(line)
        .map_err(|e| format!("not UTF-8 text (byte {})", e.valid_up_to()))?;
    let s: Sighting = serde_json::from_str(text).map_err(|e| signing::printable(&e.to_string()))?;
    if s.format != WITNESS_FORMAT {
        return Err(format!(
            "format `{}`, not `{WITNESS_FORMAT}`",
            signing::printable(&s.format)
        ));
    }
    if !signing::is_sha256_hex(&s.head_sha256) {
        return Err("head_sha256 is not a SHA-256".to_owned());
    }
    Ok(s)
}

impl Witness {
    /// Parses a witness log, bytes as read. Every whole line must be a sighting; the one thing
    /// passed over (and listed in [`Witness::unreadable`]) is an append a crash cut short: the last
    /// line without its newline, or the fragment such an append left before the next whole line on
    /// the same line. Anything else refuses the whole witness.
    pub fn parse(bytes: &[u8]) -> Result<Self, RobotError> {
        let mut witness = Self::default();
        let complete = bytes.is_empty() || bytes.ends_with(b"\n");
        let mut lines: Vec<&[u8]> = bytes.split(|b| *b == b'\n').collect();
        if complete {
            lines.pop();
        }
        let count = lines.len();
        for (i, line) in lines.into_iter().enumerate() {
            let number = i + 1;
            if line.iter().all(u8::is_ascii_whitespace) {
                continue;
            }
            if i + 1 == count && !complete {
                witness.unreadable.push(format!(
                    "line {number}: an append cut short (no newline; a crash while writing), passed over"
                ));
                continue;
            }
            match sighting(line) {
                Ok(s) => witness.sightings.push((number, s)),
                Err(why) => {
                    // A torn append, and the next append written after it on the same line.
                    let after_torn = line
                        .windows(LINE_START.len())
                        .rposition(|w| w == LINE_START)
                        .filter(|&at| at > 0)
                        .and_then(|at| sighting(&line[at..]).ok());
                    match after_torn {
                        Some(s) => {
                            witness.sightings.push((number, s));
                            witness.unreadable.push(format!(
                                "line {number}: begins with an append cut short (a crash while writing), passed over"
                            ));
                        }
                        None => {
                            return Err(RobotError::WitnessUnreadable { line: number, why });
                        }
                    }
                }
            }
        }
        Ok(witness)
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
