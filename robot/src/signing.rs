//! Signed approvals: who may sign off a locked trajectory, and the exact bytes they sign.
//!
//! An approval is an OpenSSH signature (`SSHSIG`, Ed25519) over [`approval_message`], so an engineer
//! signs with the SSH key they already hold (`ssh-keygen -Y sign`, an agent, a hardware key) and anyone
//! can check an approval with `ssh-keygen -Y verify` and the cell's own trust file, without ergocell.
//! The cryptography is the `ssh-key` crate's (RustCrypto); nothing here is a primitive of our own.
//!
//! The cell trusts the keys in two files beside its cell config, both covered by every lock
//! ([`crate::InputHashes`]), so adding or revoking a key is a change that needs a re-lock and a review:
//! - `approvers/allowed_signers` ([`ALLOWED_SIGNERS`]): OpenSSH's allowed-signers format
//!   (`ssh-keygen(1)`, "ALLOWED SIGNERS"): `principals [options] ssh-ed25519 <base64> [comment]`.
//!   Principals are exact names (no wildcards); the one option honoured is `namespaces="…"` (the key
//!   then counts only if it lists [`APPROVAL_NAMESPACE`]); `cert-authority`, `valid-after` and
//!   `valid-before` are refused rather than silently ignored. Only Ed25519 keys.
//! - `approvers/revoked_keys` ([`REVOKED_KEYS`]): one OpenSSH public key per line, the plain-list form
//!   that `ssh-keygen -Y verify -r` also reads. A listed key's approvals are refused, whatever the
//!   allowed-signers file says.

use std::fmt;

use ssh_key::{HashAlg, LineEnding, PublicKey, SshSig};

/// An SSH private key (re-exported from `ssh-key`, so callers need no second copy of the crate).
pub use ssh_key::PrivateKey;

use crate::RobotError;

/// The SSHSIG namespace of an approval (`ssh-keygen -Y sign -n …`): a signature made for anything
/// else (a git commit, a file) is never an approval.
pub const APPROVAL_NAMESPACE: &str = "ergocell-trajectory-approval";

/// The trust file, relative to the cell config's folder.
pub const ALLOWED_SIGNERS: &str = "approvers/allowed_signers";

/// The revocation list, relative to the cell config's folder.
pub const REVOKED_KEYS: &str = "approvers/revoked_keys";

/// Why an approval is refused: a field that is not well formed, or a signature that does not
/// check out against the cell's trust files.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ApprovalError {
    /// The approver's name is not one exact principal.
    #[error("approver `{approver}` {why}")]
    BadApprover { approver: String, why: &'static str },
    /// The approval time is not RFC 3339 UTC written as `YYYY-MM-DDTHH:MM:SSZ`.
    #[error("approved_at_utc `{text}` {why}")]
    BadTime { text: String, why: String },
    /// A hash field is not a lowercase hex SHA-256.
    #[error("{field} `{value}` is not a SHA-256 in lowercase hex")]
    BadHash { field: &'static str, value: String },
    /// The signature does not parse as an SSHSIG.
    #[error("the signature is not an SSH signature ({why})")]
    NotSignature { why: String },
    /// The signature was made for another purpose.
    #[error("the signature was made for namespace `{namespace}`, not `{APPROVAL_NAMESPACE}`")]
    WrongNamespace { namespace: String },
    /// The signing key is on the revocation list.
    #[error("key {fingerprint} is revoked ({list})")]
    Revoked {
        fingerprint: String,
        /// The list that revokes it: the project's [`REVOKED_KEYS`] or the site authority's.
        list: &'static str,
    },
    /// The signing key is not in the allowed-signers file.
    #[error("key {fingerprint} is not a trusted approver's key (not in {ALLOWED_SIGNERS})")]
    Untrusted { fingerprint: String },
    /// The signing key is trusted, but for other principals.
    #[error(
        "key {fingerprint} is trusted for {trusted_for}, not for `{approver}` ({ALLOWED_SIGNERS})"
    )]
    WrongPrincipal {
        fingerprint: String,
        trusted_for: String,
        approver: String,
    },
    /// The signature is not over this entry's message.
    #[error(
        "the signature does not match the entry (its class, lock hash, name, time or previous hash \
         was edited, or the signature was made for another entry)"
    )]
    Mismatch,
}

/// First line of every approval message (its format version).
const MESSAGE_HEADER: &str = "ergocell trajectory approval v1";

/// First line of every withdrawal message: a withdrawal signs other bytes than any approval, so one
/// can never be read as the other.
const WITHDRAWAL_HEADER: &str = "ergocell trajectory withdrawal v1";

/// What an entry of an approvals file says of the lock it names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Action {
    /// A sign-off: the lock may run.
    #[default]
    Approve,
    /// The sign-off is taken back: the lock may not run until it is approved again.
    Withdraw,
}

impl Action {
    /// True for [`Action::Approve`] (an approval entry writes no `action` field, so entries written
    /// before withdrawals existed keep their bytes and hashes).
    pub fn is_approve(&self) -> bool {
        *self == Action::Approve
    }

    fn header(self) -> &'static str {
        match self {
            Action::Approve => MESSAGE_HEADER,
            Action::Withdraw => WITHDRAWAL_HEADER,
        }
    }

    /// The message's names of the `approved_by` / `approved_at_utc` fields.
    fn field_names(self) -> [&'static str; 5] {
        match self {
            Action::Approve => [
                "class",
                "lock_sha256",
                "approved_by",
                "approved_at_utc",
                "previous_sha256",
            ],
            Action::Withdraw => [
                "class",
                "lock_sha256",
                "withdrawn_by",
                "withdrawn_at_utc",
                "previous_sha256",
            ],
        }
    }
}

impl Action {
    /// "an approval message" / "a withdrawal message".
    pub fn message_noun(self) -> &'static str {
        match self {
            Action::Approve => "an approval message",
            Action::Withdraw => "a withdrawal message",
        }
    }
}

impl fmt::Display for Action {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Action::Approve => "approval",
            Action::Withdraw => "withdrawal",
        })
    }
}

/// The fields an approval (or a withdrawal) signs, in the order they are written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ApprovalClaim<'a> {
    pub action: Action,
    pub class: &'a str,
    pub lock_sha256: &'a str,
    /// Who signs (for a withdrawal: who withdraws).
    pub approved_by: &'a str,
    /// When (for a withdrawal: when it was withdrawn).
    pub approved_at_utc: &'a str,
    pub previous_sha256: &'a str,
}

/// The exact bytes an approval's signature covers: the class, the lock's hash, the approver's
/// principal, the time and the previous entry's hash, one `key: value` line each after a version line
/// (a withdrawal: its own version line, and `withdrawn_by` / `withdrawn_at_utc`).
/// Editing any of them (or moving a signature to another lock, class or place in the chain) breaks it.
pub fn approval_message(claim: &ApprovalClaim<'_>) -> String {
    let [class, lock, by, at, previous] = claim.action.field_names();
    format!(
        "{}\n{class}: {}\n{lock}: {}\n{by}: {}\n{at}: {}\n{previous}: {}\n",
        claim.action.header(),
        claim.class,
        claim.lock_sha256,
        claim.approved_by,
        claim.approved_at_utc,
        claim.previous_sha256
    )
}

/// Parses a message written by [`approval_message`] back into its kind and fields (for the two-step
/// flow, where the engineer signs the message file with `ssh-keygen` and hands back message and
/// signature).
pub fn parse_approval_message(text: &str) -> Result<(Action, [String; 5]), RobotError> {
    let bad = |reason: String| RobotError::Config {
        reason: format!("not an approval message: {reason}"),
    };
    let mut lines = text.lines();
    let action = match lines.next() {
        Some(MESSAGE_HEADER) => Action::Approve,
        Some(WITHDRAWAL_HEADER) => Action::Withdraw,
        _ => {
            return Err(bad(format!(
                "the first line is neither `{MESSAGE_HEADER}` nor `{WITHDRAWAL_HEADER}`"
            )))
        }
    };
    let mut out: [String; 5] = Default::default();
    for (slot, key) in out.iter_mut().zip(action.field_names()) {
        let line = lines
            .next()
            .ok_or_else(|| bad(format!("no `{key}:` line")))?;
        let value = line
            .strip_prefix(key)
            .and_then(|rest| rest.strip_prefix(": "))
            .ok_or_else(|| bad(format!("expected `{key}: …`, found `{}`", printable(line))))?;
        value.clone_into(slot);
    }
    if lines.next().is_some() {
        return Err(bad("text after the last field".to_owned()));
    }
    if approval_message(&ApprovalClaim {
        action,
        class: &out[0],
        lock_sha256: &out[1],
        approved_by: &out[2],
        approved_at_utc: &out[3],
        previous_sha256: &out[4],
    }) != text
    {
        return Err(bad(
            "not byte for byte what `approve --message-out` writes".to_owned()
        ));
    }
    Ok((action, out))
}

/// `text` with everything but printable ASCII and the space escaped (`\n`, `\u{1b}`, `\u{202e}`, …),
/// for printing what came from a file: it cannot forge an extra line, move the cursor, colour a
/// terminal or reorder the text around it.
pub fn printable(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c == ' ' || c.is_ascii_graphic() {
            out.push(c);
        } else {
            out.extend(c.escape_default());
        }
    }
    out
}

/// Whether `text` is a SHA-256 in lowercase hex, as every hash in a lock or approval is written.
pub fn is_sha256_hex(text: &str) -> bool {
    text.len() == 64
        && text
            .bytes()
            .all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
}

/// Checks that `principal` can be an approver's name: non-empty, no whitespace, no control
/// characters, no comma or quote (the allowed-signers syntax), no wildcard.
pub fn check_principal(principal: &str) -> Result<(), RobotError> {
    approver_ok(principal).map_err(|e| RobotError::Config {
        reason: e.to_string(),
    })
}

fn approver_ok(principal: &str) -> Result<(), ApprovalError> {
    let bad = |why: &'static str| ApprovalError::BadApprover {
        approver: printable(principal),
        why,
    };
    if principal.is_empty() {
        return Err(bad("is empty"));
    }
    if principal.chars().any(|c| !c.is_ascii_graphic()) {
        return Err(bad(
            "contains whitespace, a control character or a non-ASCII character",
        ));
    }
    if principal.contains([',', '"', '*', '?', '!']) {
        return Err(bad(
            "contains one of , \" * ? ! (a principal is one exact name, as in allowed_signers)",
        ));
    }
    Ok(())
}

/// One key the cell trusts, with the principals it may sign as.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TrustedKey {
    pub principals: Vec<String>,
    pub key: PublicKey,
    /// 1-based line in the allowed-signers file.
    pub line: usize,
}

/// The keys the cell trusts for approvals, and the revoked ones.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct TrustedSigners {
    keys: Vec<TrustedKey>,
    revoked: Vec<PublicKey>,
    /// Revoked by the site authority's own list (in the trust anchor), not the project's.
    revoked_by_site: Vec<PublicKey>,
}

/// How a key revoked by the site authority's list (the trust anchor's `revoked_keys`) is named.
pub const SITE_REVOKED_KEYS: &str = "the site authority's revoked_keys in the trust anchor";

/// `SHA256:…` fingerprint, as `ssh-keygen -l` prints it.
pub fn fingerprint(key: &PublicKey) -> String {
    key.fingerprint(HashAlg::Sha256).to_string()
}

impl TrustedSigners {
    /// Parses the allowed-signers file and the revocation list (see the module docs for what each
    /// may hold). Any line it cannot honour exactly is an error naming the line: trust is never
    /// guessed.
    pub fn parse(allowed_signers: &str, revoked_keys: &str) -> Result<Self, RobotError> {
        let mut keys = Vec::new();
        for (i, raw) in allowed_signers.lines().enumerate() {
            let line = raw.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            keys.push(parse_allowed_signer(line, i + 1)?);
        }
        let mut revoked = Vec::new();
        for (i, raw) in revoked_keys.lines().enumerate() {
            let line = raw.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let key = PublicKey::from_openssh(line).map_err(|e| RobotError::Config {
                reason: format!(
                    "{REVOKED_KEYS} line {}: not an OpenSSH public key ({e})",
                    i + 1
                ),
            })?;
            revoked.push(key);
        }
        Ok(Self {
            keys,
            revoked,
            revoked_by_site: Vec::new(),
        })
    }

    /// The listed keys (revoked ones included: see [`Self::usable_keys`]).
    pub fn keys(&self) -> &[TrustedKey] {
        &self.keys
    }

    /// How many listed keys can sign an approval (listed and on no revocation list).
    pub fn usable_keys(&self) -> usize {
        self.keys
            .iter()
            .filter(|k| !self.is_revoked(&k.key))
            .count()
    }

    /// Adds the site authority's own revocations to the project's.
    pub fn revoke_also(&mut self, keys: &[PublicKey]) {
        self.revoked_by_site.extend(keys.iter().cloned());
    }

    /// Whether `key` is on a revocation list.
    pub fn is_revoked(&self, key: &PublicKey) -> bool {
        self.revoked_by(key).is_some()
    }

    /// The list that revokes `key`, if one does.
    fn revoked_by(&self, key: &PublicKey) -> Option<&'static str> {
        let on = |list: &[PublicKey]| list.iter().any(|r| r.key_data() == key.key_data());
        if on(&self.revoked) {
            Some(REVOKED_KEYS)
        } else if on(&self.revoked_by_site) {
            Some(SITE_REVOKED_KEYS)
        } else {
            None
        }
    }

    /// Signs `claim` with `key`, after checking that the key is trusted for the claim's principal and
    /// not revoked (a signature the cell would refuse is never written). Returns the armored
    /// signature (`-----BEGIN SSH SIGNATURE-----`).
    pub fn sign(&self, claim: &ApprovalClaim<'_>, key: &PrivateKey) -> Result<String, RobotError> {
        let public = key.public_key();
        self.check_signer(claim.approved_by, public)
            .map_err(|e| RobotError::Config {
                reason: e.to_string(),
            })?;
        let message = approval_message(claim);
        let sig = key
            .sign(APPROVAL_NAMESPACE, HashAlg::Sha512, message.as_bytes())
            .map_err(|e| RobotError::Config {
                reason: format!("signing failed: {e}"),
            })?;
        sig.to_pem(LineEnding::LF).map_err(|e| RobotError::Config {
            reason: format!("cannot armor the signature: {e}"),
        })
    }

    /// Checks one approval: its time is RFC 3339 UTC, `signature` is an SSHSIG in the approval
    /// namespace, by a key the allowed-signers file lists for `claim.approved_by`, not revoked, over
    /// exactly [`approval_message`]`(claim)`. The error says which of these failed.
    pub fn verify(&self, claim: &ApprovalClaim<'_>, signature: &str) -> Result<(), ApprovalError> {
        check_claim(claim)?;
        let sig = SshSig::from_pem(signature.trim())
            .map_err(|e| ApprovalError::NotSignature { why: e.to_string() })?;
        if sig.namespace() != APPROVAL_NAMESPACE {
            return Err(ApprovalError::WrongNamespace {
                namespace: printable(sig.namespace()),
            });
        }
        let public = PublicKey::from(sig.public_key().clone());
        self.check_signer(claim.approved_by, &public)?;
        public
            .verify(APPROVAL_NAMESPACE, approval_message(claim).as_bytes(), &sig)
            .map_err(|_| ApprovalError::Mismatch)
    }

    fn check_signer(&self, principal: &str, key: &PublicKey) -> Result<(), ApprovalError> {
        approver_ok(principal)?;
        let fingerprint = fingerprint(key);
        if let Some(list) = self.revoked_by(key) {
            return Err(ApprovalError::Revoked { fingerprint, list });
        }
        let listed = self
            .keys
            .iter()
            .filter(|k| k.key.key_data() == key.key_data())
            .collect::<Vec<_>>();
        if listed.is_empty() {
            return Err(ApprovalError::Untrusted { fingerprint });
        }
        if !listed
            .iter()
            .any(|k| k.principals.iter().any(|p| p == principal))
        {
            return Err(ApprovalError::WrongPrincipal {
                fingerprint,
                trusted_for: listed
                    .iter()
                    .flat_map(|k| k.principals.iter().map(|p| format!("`{p}`")))
                    .collect::<Vec<_>>()
                    .join(", "),
                approver: printable(principal),
            });
        }
        Ok(())
    }
}

impl fmt::Display for TrustedKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({}, line {})",
            self.principals.join(","),
            fingerprint(&self.key),
            self.line
        )
    }
}

/// Checks `text` is an RFC 3339 time in UTC (`…Z` or `+00:00`).
pub fn check_utc_time(text: &str) -> Result<(), ApprovalError> {
    utc_unix_time(text).map(|_| ())
}

/// [`check_utc_time`], giving the time in Unix seconds.
fn utc_unix_time(text: &str) -> Result<i64, ApprovalError> {
    let bad = |why: String| ApprovalError::BadTime {
        text: printable(text),
        why,
    };
    let t = time::OffsetDateTime::parse(text, &time::format_description::well_known::Rfc3339)
        .map_err(|e| bad(format!("is not an RFC 3339 time ({e})")))?;
    if !t.offset().is_utc() {
        return Err(bad("is not in UTC".to_owned()));
    }
    if rfc3339_utc(t.unix_timestamp()).ok().as_deref() != Some(text) {
        return Err(bad("is not written as YYYY-MM-DDTHH:MM:SSZ".to_owned()));
    }
    Ok(t.unix_timestamp())
}

/// The earliest time an approval may bear: ergocell's signed approvals did not exist before.
pub const EARLIEST_APPROVAL_UTC: &str = "2026-01-01T00:00:00Z";
const EARLIEST_APPROVAL_UNIX: i64 = 1_767_225_600;

/// How far in the future of the verifying machine's clock an approval's time may be: a day. The
/// approving machine's clock and the cell PC's may disagree, and the cell's may be stepped back
/// mid-session (NTP, a wrong time set by hand) while the robot must keep serving; a date years
/// ahead is still refused.
pub const APPROVAL_CLOCK_SKEW_S: i64 = 86_400;

/// Checks that an approval's time (already well formed, [`check_utc_time`]) is one an approval can
/// bear at `now_unix` (seconds, the verifying machine's clock): not before
/// [`EARLIEST_APPROVAL_UTC`] and not more than [`APPROVAL_CLOCK_SKEW_S`] in the future. A date of
/// 1970 or 2099 is a wrong clock or a made-up entry, and is refused either way.
pub fn check_approval_time(text: &str, now_unix: i64) -> Result<(), ApprovalError> {
    let t = utc_unix_time(text)?;
    let bad = |why: String| ApprovalError::BadTime {
        text: printable(text),
        why,
    };
    if t < EARLIEST_APPROVAL_UNIX {
        return Err(bad(format!(
            "is before {EARLIEST_APPROVAL_UTC}, when ergocell's signed approvals began"
        )));
    }
    if t > now_unix.saturating_add(APPROVAL_CLOCK_SKEW_S) {
        return Err(bad(format!(
            "is in the future of this machine's clock ({}): a wrong clock where it was signed, or \
             a made-up entry",
            rfc3339_utc(now_unix).unwrap_or_else(|_| now_unix.to_string())
        )));
    }
    Ok(())
}

/// Checks the fields of a claim read from a file before they are shown or trusted: the principal,
/// the time, and both hashes as lowercase hex.
pub fn check_claim(claim: &ApprovalClaim<'_>) -> Result<(), ApprovalError> {
    approver_ok(claim.approved_by)?;
    check_utc_time(claim.approved_at_utc)?;
    for (field, value) in [
        ("lock_sha256", claim.lock_sha256),
        ("previous_sha256", claim.previous_sha256),
    ] {
        if !is_sha256_hex(value) {
            return Err(ApprovalError::BadHash {
                field,
                value: printable(value),
            });
        }
    }
    Ok(())
}

/// The next field of an allowed-signers line (split on spaces and tabs, as OpenSSH does, keeping
/// double-quoted runs whole) and the rest of the line after it.
fn next_field(line: &str) -> Result<Option<(&str, &str)>, String> {
    let line = line.trim_start_matches([' ', '\t']);
    if line.is_empty() {
        return Ok(None);
    }
    let mut quoted = false;
    for (i, c) in line.char_indices() {
        match c {
            '"' => quoted = !quoted,
            ' ' | '\t' if !quoted => return Ok(Some((&line[..i], &line[i..]))),
            _ => {}
        }
    }
    if quoted {
        return Err("unterminated quote".to_owned());
    }
    Ok(Some((line, "")))
}

/// Splits an options field on the commas outside double quotes (`namespaces="a,b",cert-authority`).
fn split_options(options: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut start = 0;
    let mut quoted = false;
    for (i, c) in options.char_indices() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => {
                out.push(&options[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&options[start..]);
    out
}

fn parse_allowed_signer(line: &str, number: usize) -> Result<TrustedKey, RobotError> {
    let bad = |reason: String| RobotError::Config {
        reason: format!("{ALLOWED_SIGNERS} line {number}: {reason}"),
    };
    let shape = || bad("expected `principals [options] keytype base64-key [comment]`".to_owned());
    let (principals, rest) = next_field(line).map_err(bad)?.ok_or_else(shape)?;
    let (second, rest) = next_field(rest).map_err(bad)?.ok_or_else(shape)?;
    let is_keytype =
        |t: &str| t.starts_with("ssh-") || t.starts_with("ecdsa-") || t.starts_with("sk-");
    let (options, keytype, rest) = if is_keytype(second) {
        (None, second, rest)
    } else {
        let (keytype, rest) = next_field(rest).map_err(bad)?.ok_or_else(shape)?;
        (Some(second), keytype, rest)
    };
    // The key; the rest of the line is its comment, whatever it holds.
    let (base64, _comment) = next_field(rest).map_err(bad)?.ok_or_else(shape)?;
    if keytype != "ssh-ed25519" {
        return Err(bad(format!(
            "key type `{}`: only ssh-ed25519 keys may approve",
            printable(keytype)
        )));
    }
    if let Some(options) = options {
        for option in split_options(options) {
            let (name, value) = option.split_once('=').unwrap_or((option, ""));
            match name.to_ascii_lowercase().as_str() {
                "namespaces" => {
                    let list = value.trim_matches('"');
                    if list.contains(['!', '*', '?']) {
                        return Err(bad(format!(
                            "namespaces=\"{}\": patterns are not supported, list the namespaces exactly",
                            printable(list)
                        )));
                    }
                    if !list.split(',').any(|n| n == APPROVAL_NAMESPACE) {
                        return Err(bad(format!(
                            "namespaces=\"{}\" does not list `{APPROVAL_NAMESPACE}`: this key may not approve",
                            printable(list)
                        )));
                    }
                }
                other => {
                    return Err(bad(format!(
                        "option `{}` is not supported by ergocell (only namespaces=\"…\"); \
                         remove it or use the revocation list to retire a key",
                        printable(other)
                    )))
                }
            }
        }
    }
    let principals: Vec<String> = principals.split(',').map(str::to_owned).collect();
    for p in &principals {
        check_principal(p).map_err(|e| bad(e.to_string()))?;
    }
    let key = PublicKey::from_openssh(&format!("{keytype} {base64}"))
        .map_err(|e| bad(format!("not an OpenSSH public key ({e})")))?;
    Ok(TrustedKey {
        principals,
        key,
        line: number,
    })
}

/// A 32-byte key seed derived from a label and a number (SHA-256 of both): the demo's key from its
/// `--seed`, so the same seed gives the same demo lock hashes. Anyone can derive it again, so such a key
/// proves nothing outside the run that trusts it.
pub fn derived_seed(label: &str, n: u64) -> [u8; 32] {
    use sha2::Digest as _;
    let mut h = sha2::Sha256::new();
    h.update(label.as_bytes());
    h.update(n.to_le_bytes());
    h.finalize().into()
}

/// An Ed25519 SSH key from a 32-byte seed (the demo's throwaway key, tests' fixed keys).
pub fn key_from_seed(seed: &[u8; 32], comment: &str) -> PrivateKey {
    let mut key = PrivateKey::from(ssh_key::private::Ed25519Keypair::from_seed(seed));
    key.set_comment(comment);
    key
}

/// Parses an OpenSSH private key (`-----BEGIN OPENSSH PRIVATE KEY-----`). A passphrase-protected key
/// is refused with the way round it: sign the approval message with `ssh-keygen` (which asks for the
/// passphrase, or uses the agent) and hand the signature back.
pub fn private_key_from_openssh(text: &str) -> Result<PrivateKey, RobotError> {
    let key = PrivateKey::from_openssh(text).map_err(|e| RobotError::Config {
        reason: format!("not an OpenSSH private key ({e})"),
    })?;
    if key.is_encrypted() {
        return Err(RobotError::Config {
            reason:
                "the key is passphrase-protected: write the message with `approve --message-out`, \
                     sign it with `ssh-keygen -Y sign`, then `approve --signed`"
                    .to_owned(),
        });
    }
    if key.algorithm() != ssh_key::Algorithm::Ed25519 {
        return Err(RobotError::Config {
            reason: format!("only ssh-ed25519 keys may approve, not {}", key.algorithm()),
        });
    }
    Ok(key)
}

/// The key's public half as one OpenSSH line (`ssh-ed25519 AAAA… comment`).
pub fn public_key_openssh(key: &PrivateKey) -> Result<String, RobotError> {
    key.public_key()
        .to_openssh()
        .map_err(|e| RobotError::Config {
            reason: format!("cannot encode the public key: {e}"),
        })
}

/// The key's private half in OpenSSH's format (for writing a generated key to a file).
pub fn private_key_openssh(key: &PrivateKey) -> Result<String, RobotError> {
    key.to_openssh(LineEnding::LF)
        .map(|s| s.to_string())
        .map_err(|e| RobotError::Config {
            reason: format!("cannot encode the private key: {e}"),
        })
}

/// RFC 3339 UTC of a Unix time in whole seconds (`2026-12-02T02:30:00Z`), as approvals record it.
pub fn rfc3339_utc(unix_secs: i64) -> Result<String, RobotError> {
    let t =
        time::OffsetDateTime::from_unix_timestamp(unix_secs).map_err(|e| RobotError::Config {
            reason: format!("unix time {unix_secs} is out of range ({e})"),
        })?;
    t.format(&time::format_description::well_known::Rfc3339)
        .map_err(|e| RobotError::Config {
            reason: format!("cannot format unix time {unix_secs}: {e}"),
        })
}
