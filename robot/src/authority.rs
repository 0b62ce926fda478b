//! The site's approvers authority: the trust anchor above the approvers' files.
//!
//! The keys that may approve a locked trajectory are listed in the project folder
//! (`approvers/allowed_signers`, `approvers/revoked_keys`), which the cell's service account and
//! anyone with a checkout can edit. Editing them must not be enough to approve a motion, so the pair
//! counts only when the site's **approvers authority** has signed it: an OpenSSH signature
//! ([`APPROVERS_SIGNATURE`], namespace [`APPROVERS_NAMESPACE`]) over [`approvers_message`], made by a
//! key whose public half is installed apart from the project, read-only to the cell (the binary
//! checks where it lives; this module only checks signatures). An appended key, a loosened class
//! re-locked and self-approved, or a revocation removed, breaks that signature and every approval
//! under the edited files is refused, naming why.
//!
//! The anchor may also carry its own revocation list: a key revoked there is refused whatever the
//! project's files say, and no checkout restored from history brings it back.
//!
//! A list that trusts no key needs no signature: it can approve nothing (the shipped cell).

use ssh_key::{HashAlg, LineEnding, PublicKey, SshSig};

use crate::signing::{self, printable, PrivateKey, TrustedSigners};
use crate::validate::sha256_hex;
use crate::RobotError;

/// The SSHSIG namespace of the authority's signature over the approvers' files
/// (`ssh-keygen -Y sign -n ergocell-approvers`): an approval or any other signature never counts.
pub const APPROVERS_NAMESPACE: &str = "ergocell-approvers";

/// The authority's signature over the approvers' files, relative to the cell config's folder.
pub const APPROVERS_SIGNATURE: &str = "approvers/approvers.sig";

/// Why the approvers' files are not trusted.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum AuthorityError {
    /// The files list keys but there is no signature.
    #[error(
        "{ALLOWED_SIGNERS} lists {keys} key(s) but {APPROVERS_SIGNATURE} is missing: the site's \
         approvers authority must sign the approvers' files (`ergocell trajectories sign-approvers`)",
        ALLOWED_SIGNERS = signing::ALLOWED_SIGNERS
    )]
    Unsigned { keys: usize },
    /// The files list keys but the site has no approvers authority installed.
    #[error(
        "{ALLOWED_SIGNERS} lists {keys} key(s) but no approvers authority is installed ({why}): \
         the keys in the project folder are trusted only under the site's authority key",
        ALLOWED_SIGNERS = signing::ALLOWED_SIGNERS
    )]
    NoAuthority { keys: usize, why: String },
    /// The signature file is not an SSH signature.
    #[error("{APPROVERS_SIGNATURE} is not an SSH signature ({why})")]
    NotSignature { why: String },
    /// The signature was made for another purpose.
    #[error(
        "{APPROVERS_SIGNATURE} was made for namespace `{namespace}`, not `{APPROVERS_NAMESPACE}`"
    )]
    WrongNamespace { namespace: String },
    /// The signature is by a key that is not the site's authority.
    #[error(
        "{APPROVERS_SIGNATURE} is signed by key {fingerprint}, which is not the site's approvers \
         authority ({authority})"
    )]
    NotAuthority {
        fingerprint: String,
        authority: String,
    },
    /// The files were changed after the authority signed them.
    #[error(
        "the approvers' files are not what the site's approvers authority signed: {ALLOWED_SIGNERS} \
         or {REVOKED_KEYS} was edited after signing (a key added, removed or un-revoked)",
        ALLOWED_SIGNERS = signing::ALLOWED_SIGNERS,
        REVOKED_KEYS = signing::REVOKED_KEYS
    )]
    Edited,
    /// The approvers' files themselves do not parse.
    #[error("{0}")]
    Files(String),
}

/// The exact bytes the authority signs: both files' SHA-256, so one signature covers the pair and
/// any edit to either breaks it.
pub fn approvers_message(allowed_signers: &str, revoked_keys: &str) -> String {
    format!(
        "ergocell approvers v1\nallowed_signers_sha256 {}\nrevoked_keys_sha256 {}\n",
        sha256_hex(allowed_signers.as_bytes()),
        sha256_hex(revoked_keys.as_bytes())
    )
}

/// The site's approvers authority: its keys (more than one while a key is rotated) and the
/// revocations that live with it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Authority {
    keys: Vec<PublicKey>,
    revoked: Vec<PublicKey>,
}

fn parse_keys(text: &str, what: &str) -> Result<Vec<PublicKey>, RobotError> {
    let mut keys = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let key = PublicKey::from_openssh(line).map_err(|e| RobotError::Config {
            reason: format!("{what} line {}: not an OpenSSH public key ({e})", i + 1),
        })?;
        keys.push(key);
    }
    Ok(keys)
}

impl Authority {
    /// Parses the authority's public keys (one OpenSSH public key a line, `#` comments; only
    /// ssh-ed25519) and its revocation list (same format; may be empty).
    pub fn parse(keys: &str, revoked_keys: &str) -> Result<Self, RobotError> {
        let keys = parse_keys(keys, "the authority's key file")?;
        if keys.is_empty() {
            return Err(RobotError::Config {
                reason: "the authority's key file lists no key".to_owned(),
            });
        }
        if let Some(k) = keys
            .iter()
            .find(|k| k.algorithm() != ssh_key::Algorithm::Ed25519)
        {
            return Err(RobotError::Config {
                reason: format!(
                    "the authority's key file: only ssh-ed25519 keys, not {}",
                    k.algorithm()
                ),
            });
        }
        let revoked = parse_keys(revoked_keys, "the authority's revoked_keys")?;
        Ok(Self { keys, revoked })
    }

    /// The authority's keys' fingerprints, comma-separated (for messages).
    pub fn fingerprints(&self) -> String {
        self.keys
            .iter()
            .map(signing::fingerprint)
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The authority's own revocations.
    pub fn revoked(&self) -> &[PublicKey] {
        &self.revoked
    }

    /// Checks the authority's `signature` over the files and returns the signers they trust, with
    /// the authority's own revocations added.
    pub fn verify(
        &self,
        allowed_signers: &str,
        revoked_keys: &str,
        signature: &str,
    ) -> Result<TrustedSigners, AuthorityError> {
        let mut trusted = TrustedSigners::parse(allowed_signers, revoked_keys)
            .map_err(|e| AuthorityError::Files(e.to_string()))?;
        let sig = SshSig::from_pem(signature.trim())
            .map_err(|e| AuthorityError::NotSignature { why: e.to_string() })?;
        if sig.namespace() != APPROVERS_NAMESPACE {
            return Err(AuthorityError::WrongNamespace {
                namespace: printable(sig.namespace()),
            });
        }
        let public = PublicKey::from(sig.public_key().clone());
        if !self.keys.iter().any(|k| k.key_data() == public.key_data()) {
            return Err(AuthorityError::NotAuthority {
                fingerprint: signing::fingerprint(&public),
                authority: self.fingerprints(),
            });
        }
        public
            .verify(
                APPROVERS_NAMESPACE,
                approvers_message(allowed_signers, revoked_keys).as_bytes(),
                &sig,
            )
            .map_err(|_| AuthorityError::Edited)?;
        trusted.revoke_also(&self.revoked);
        Ok(trusted)
    }
}

/// Signs the approvers' files with `key` (the authority's private key) for [`APPROVERS_SIGNATURE`];
/// the same as `ssh-keygen -Y sign -n ergocell-approvers` over [`approvers_message`]. Returns the
/// armored signature.
pub fn sign_approvers(
    allowed_signers: &str,
    revoked_keys: &str,
    key: &PrivateKey,
) -> Result<String, RobotError> {
    let sig = key
        .sign(
            APPROVERS_NAMESPACE,
            HashAlg::Sha512,
            approvers_message(allowed_signers, revoked_keys).as_bytes(),
        )
        .map_err(|e| RobotError::Config {
            reason: format!("signing failed: {e}"),
        })?;
    sig.to_pem(LineEnding::LF).map_err(|e| RobotError::Config {
        reason: format!("cannot armor the signature: {e}"),
    })
}

/// The signers the cell trusts, given the approvers' files, the authority's signature over them
/// (if any) and the installed authority (or why there is none). A list that trusts no key is
/// returned as it is (it approves nothing); one that trusts keys needs the authority's signature.
pub fn anchored_signers(
    allowed_signers: &str,
    revoked_keys: &str,
    signature: Option<&str>,
    authority: Result<&Authority, &str>,
) -> Result<TrustedSigners, AuthorityError> {
    let listed = TrustedSigners::parse(allowed_signers, revoked_keys)
        .map_err(|e| AuthorityError::Files(e.to_string()))?;
    let keys = listed.keys().len();
    if keys == 0 {
        return Ok(listed);
    }
    let authority = authority.map_err(|why| AuthorityError::NoAuthority {
        keys,
        why: why.to_owned(),
    })?;
    let signature = signature.ok_or(AuthorityError::Unsigned { keys })?;
    authority.verify(allowed_signers, revoked_keys, signature)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::signing::{key_from_seed, public_key_openssh, APPROVAL_NAMESPACE};

    fn line(seed: u8, principal: &str) -> String {
        let key = key_from_seed(&[seed; 32], principal);
        format!(
            "{principal} namespaces=\"{APPROVAL_NAMESPACE}\" {}\n",
            public_key_openssh(&key).unwrap()
        )
    }

    fn site() -> (PrivateKey, Authority) {
        let key = key_from_seed(&[90; 32], "site authority");
        let authority = Authority::parse(&public_key_openssh(&key).unwrap(), "").unwrap();
        (key, authority)
    }

    #[test]
    fn the_signed_list_is_trusted_and_any_edit_is_refused() {
        let (key, authority) = site();
        let allowed = line(1, "alice@plant.example");
        let sig = sign_approvers(&allowed, "", &key).unwrap();
        let trusted = anchored_signers(&allowed, "", Some(&sig), Ok(&authority)).unwrap();
        assert_eq!(trusted.keys().len(), 1);

        // Mallory appends her own key: the signature no longer covers the file.
        let edited = format!("{allowed}{}", line(3, "mallory@evil"));
        assert_eq!(
            anchored_signers(&edited, "", Some(&sig), Ok(&authority)),
            Err(AuthorityError::Edited)
        );
        // A revocation removed is an edit as well.
        let revoked = public_key_openssh(&key_from_seed(&[2; 32], "bob")).unwrap();
        let sig2 = sign_approvers(&allowed, &revoked, &key).unwrap();
        assert!(anchored_signers(&allowed, &revoked, Some(&sig2), Ok(&authority)).is_ok());
        assert_eq!(
            anchored_signers(&allowed, "", Some(&sig2), Ok(&authority)),
            Err(AuthorityError::Edited)
        );
    }

    #[test]
    fn a_signature_by_anyone_but_the_authority_or_for_another_purpose_is_refused() {
        let (_, authority) = site();
        let allowed = line(1, "alice@plant.example");
        let mallory = key_from_seed(&[3; 32], "mallory");
        // Mallory's own "authority" signs her list: not the site's key.
        let sig = sign_approvers(&allowed, "", &mallory).unwrap();
        assert!(matches!(
            anchored_signers(&allowed, "", Some(&sig), Ok(&authority)),
            Err(AuthorityError::NotAuthority { .. })
        ));
        // The site's key, but an approval's namespace.
        let (key, _) = site();
        let other = key
            .sign(
                APPROVAL_NAMESPACE,
                HashAlg::Sha512,
                approvers_message(&allowed, "").as_bytes(),
            )
            .unwrap()
            .to_pem(LineEnding::LF)
            .unwrap();
        assert!(matches!(
            anchored_signers(&allowed, "", Some(&other), Ok(&authority)),
            Err(AuthorityError::WrongNamespace { .. })
        ));
        assert!(matches!(
            anchored_signers(&allowed, "", Some("not a signature"), Ok(&authority)),
            Err(AuthorityError::NotSignature { .. })
        ));
    }

    #[test]
    fn keys_without_a_signature_or_an_authority_are_not_trusted_and_an_empty_list_needs_neither() {
        let (_, authority) = site();
        let allowed = line(1, "alice@plant.example");
        assert_eq!(
            anchored_signers(&allowed, "", None, Ok(&authority)),
            Err(AuthorityError::Unsigned { keys: 1 })
        );
        assert!(matches!(
            anchored_signers(&allowed, "", None, Err("not installed")),
            Err(AuthorityError::NoAuthority { keys: 1, .. })
        ));
        let empty = "# trusts no one\n";
        let trusted = anchored_signers(empty, "", None, Err("not installed")).unwrap();
        assert!(trusted.keys().is_empty());
    }

    #[test]
    fn the_authoritys_own_revocations_hold_whatever_the_project_files_say() {
        let (key, _) = site();
        let alice = key_from_seed(&[1; 32], "alice");
        let authority = Authority::parse(
            &public_key_openssh(&key).unwrap(),
            &public_key_openssh(&alice).unwrap(),
        )
        .unwrap();
        let allowed = line(1, "alice@plant.example");
        let sig = sign_approvers(&allowed, "", &key).unwrap();
        let trusted = anchored_signers(&allowed, "", Some(&sig), Ok(&authority)).unwrap();
        assert!(trusted.is_revoked(alice.public_key()));
        assert_eq!((trusted.keys().len(), trusted.usable_keys()), (1, 0));
        // Her signature is refused naming the list that revokes her: the site's, not the project's.
        let claim = crate::signing::ApprovalClaim {
            action: crate::signing::Action::Approve,
            class: "c2",
            lock_sha256: &"0".repeat(64),
            approved_by: "alice@plant.example",
            approved_at_utc: "2026-01-02T00:00:00Z",
            previous_sha256: "",
        };
        let refused = trusted.sign(&claim, &alice).unwrap_err().to_string();
        assert!(
            refused.contains(crate::signing::SITE_REVOKED_KEYS)
                && !refused.contains(crate::signing::REVOKED_KEYS),
            "{refused}"
        );
    }

    #[test]
    fn the_authority_file_must_hold_ed25519_keys() {
        assert!(Authority::parse("# nothing\n", "").is_err());
        assert!(Authority::parse("ssh-ed25519 not-base64", "").is_err());
    }
}
