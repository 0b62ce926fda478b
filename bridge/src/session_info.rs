//! Who a recording served: the operator's pseudonymous id, written once per recording as an MCAP
//! metadata record ([`METADATA_NAME`]) and read back by the review and `ergocell exposure`.
//!
//! Posture data of a named worker is personal data. The cell never stores a name: the plant keeps
//! the mapping from its people to these ids, and a recording (and everything summarised from it)
//! carries only the id. An id is therefore restricted to a short token of letters, digits and
//! `-`, `_`, `.` — no spaces, so a full name is not typed in by habit.

use std::collections::BTreeMap;
use std::fmt;

/// The MCAP metadata record's name.
pub const METADATA_NAME: &str = "ergocell.session";
/// Its key for the operator's id.
pub const OPERATOR_KEY: &str = "operator";
/// The longest id accepted, characters.
pub const OPERATOR_ID_MAX_LEN: usize = 64;

/// An operator's pseudonymous id (see the module docs).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct OperatorId(String);

/// Why a text is not an operator id.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("operator id {given:?}: {why} (a pseudonymous id: 1 to {OPERATOR_ID_MAX_LEN} letters, digits, '-', '_' or '.'; never a name)")]
pub struct OperatorIdError {
    pub given: String,
    pub why: &'static str,
}

impl OperatorId {
    /// Checks `id` (see the module docs).
    ///
    /// # Errors
    /// [`OperatorIdError`] for an empty or too long id, or one with any other character.
    pub fn new(id: &str) -> Result<Self, OperatorIdError> {
        let err = |why| OperatorIdError {
            given: id.chars().take(80).collect(),
            why,
        };
        if id.is_empty() {
            return Err(err("empty"));
        }
        if id.chars().count() > OPERATOR_ID_MAX_LEN {
            return Err(err("too long"));
        }
        if !id
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))
        {
            return Err(err("only letters, digits, '-', '_' and '.' are allowed"));
        }
        Ok(Self(id.to_owned()))
    }

    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl fmt::Display for OperatorId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// The metadata record's entries for `operator`.
pub fn metadata(operator: &OperatorId) -> BTreeMap<String, String> {
    BTreeMap::from([(OPERATOR_KEY.to_owned(), operator.0.clone())])
}

/// The operator of a metadata record's entries: `None` when the record names none, an error when
/// the id recorded is not a valid one (a damaged or hand-edited file).
///
/// # Errors
/// [`OperatorIdError`] as for [`OperatorId::new`].
pub fn operator_of(
    entries: &BTreeMap<String, String>,
) -> Result<Option<OperatorId>, OperatorIdError> {
    entries
        .get(OPERATOR_KEY)
        .map(|id| OperatorId::new(id))
        .transpose()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pseudonymous_ids_are_accepted_and_names_refused() {
        for ok in ["op-0412", "A7", "line3.station2_op17"] {
            assert_eq!(
                OperatorId::new(ok).map(|o| o.to_string()),
                Ok(ok.to_owned())
            );
        }
        for (bad, why) in [
            ("", "empty"),
            ("Anna Schmidt", "only"),
            ("jürgen", "only"),
            ("a/b", "only"),
        ] {
            let e = OperatorId::new(bad).unwrap_err();
            assert!(e.why.starts_with(why), "{bad:?}: {e}");
        }
        assert!(OperatorId::new(&"x".repeat(OPERATOR_ID_MAX_LEN)).is_ok());
        assert!(OperatorId::new(&"x".repeat(OPERATOR_ID_MAX_LEN + 1)).is_err());
    }

    #[test]
    fn the_metadata_round_trips() {
        let id = OperatorId::new("op-7").unwrap();
        assert_eq!(operator_of(&metadata(&id)), Ok(Some(id)));
        assert_eq!(operator_of(&BTreeMap::new()), Ok(None));
        let damaged = BTreeMap::from([(OPERATOR_KEY.to_owned(), "a b".to_owned())]);
        assert!(operator_of(&damaged).is_err());
    }
}
