use crate::plane::OffsetError;

/// Why a CAM computation could not be done.
#[derive(Debug, Clone, PartialEq)]
pub enum CamError {
    /// An option is out of its range: which one, and its value.
    BadOption {
        /// The option's name as in the options struct.
        name: &'static str,
        /// The value given.
        value: f64,
        /// The range it must lie in, in words ("a finite number > 0").
        expected: &'static str,
    },
    /// The offsets failed.
    Offset(OffsetError),
}

impl std::fmt::Display for CamError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CamError::BadOption { name, value, expected } => {
                write!(f, "option {name} = {value} is out of range: it must be {expected}")
            }
            CamError::Offset(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for CamError {}

impl From<OffsetError> for CamError {
    fn from(e: OffsetError) -> Self {
        CamError::Offset(e)
    }
}
