//! The formats' errors are perception's ([`PerceptionError`]): a file that cannot be read is a
//! [`PerceptionError::Parse`] naming the file and the field, and a rig it describes is checked by
//! [`ergocell_perception::CameraRig::new`], whose refusals pass through unchanged.

pub use ergocell_perception::error::{PerceptionError, Result};

/// A [`PerceptionError::Parse`] for `field` of `source_name`.
pub(crate) fn parse_err(
    source_name: &str,
    field: impl Into<String>,
    message: impl std::fmt::Display,
) -> PerceptionError {
    PerceptionError::Parse {
        source_name: source_name.to_owned(),
        field: field.into(),
        message: message.to_string(),
    }
}
