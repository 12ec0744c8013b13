//! Data a lab passes beside the shared fields of [`super::TruthState`] and
//! [`super::Measurements`]: its truth's own state for its sensors (paper 2's wheels), or
//! what its flight computer knows for the estimators that read it (paper 2's orbit and
//! models, paper 4's controller command). Typed by the lab or the estimator that reads it,
//! opaque to the loop, so a new lab adds its own type instead of a field every lab carries.

use std::any::Any;
use std::fmt;
use std::sync::Arc;

/// One value of a type the lab chooses, or nothing.
///
/// ```
/// # use attlab::model::LabData;
/// #[derive(Debug, PartialEq)]
/// struct Wheels(f64);
/// let d = LabData::new(Wheels(0.1));
/// assert_eq!(d.get::<Wheels>(), Some(&Wheels(0.1)));
/// assert_eq!(d.get::<f64>(), None);
/// assert_eq!(d, LabData::new(Wheels(0.1)));
/// assert!(LabData::default().get::<Wheels>().is_none());
/// ```
#[derive(Clone, Default)]
pub struct LabData(Option<Held>);

#[derive(Clone)]
struct Held {
    value: Arc<dyn Any + Send + Sync>,
    /// Compares two values of the held type (false for any other type).
    eq: fn(&dyn Any, &dyn Any) -> bool,
    /// Writes the held value for `Debug`.
    fmt: fn(&dyn Any, &mut fmt::Formatter<'_>) -> fmt::Result,
}

impl LabData {
    /// `value`, typed.
    pub fn new<T: Any + Send + Sync + PartialEq + fmt::Debug>(value: T) -> Self {
        fn eq<T: Any + PartialEq>(a: &dyn Any, b: &dyn Any) -> bool {
            matches!((a.downcast_ref::<T>(), b.downcast_ref::<T>()), (Some(a), Some(b)) if a == b)
        }
        fn show<T: Any + fmt::Debug>(v: &dyn Any, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            match v.downcast_ref::<T>() {
                Some(v) => v.fmt(f),
                None => f.write_str("?"),
            }
        }
        Self(Some(Held {
            value: Arc::new(value),
            eq: eq::<T>,
            fmt: show::<T>,
        }))
    }

    /// The value, if it is a `T`.
    pub fn get<T: Any>(&self) -> Option<&T> {
        self.0.as_ref()?.value.downcast_ref()
    }
}

impl PartialEq for LabData {
    fn eq(&self, other: &Self) -> bool {
        match (&self.0, &other.0) {
            (None, None) => true,
            (Some(a), Some(b)) => (a.eq)(a.value.as_ref(), b.value.as_ref()),
            _ => false,
        }
    }
}

impl fmt::Debug for LabData {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            None => f.write_str("LabData(none)"),
            Some(h) => {
                f.write_str("LabData(")?;
                (h.fmt)(h.value.as_ref(), f)?;
                f.write_str(")")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, PartialEq)]
    struct A(u8);
    #[derive(Debug, PartialEq)]
    struct B(u8);

    #[test]
    fn values_of_other_types_or_values_differ() {
        assert_ne!(LabData::new(A(1)), LabData::new(B(1)));
        assert_ne!(LabData::new(A(1)), LabData::new(A(2)));
        assert_ne!(LabData::new(A(1)), LabData::default());
        assert_eq!(LabData::default(), LabData::default());
        assert_eq!(format!("{:?}", LabData::new(A(3))), "LabData(A(3))");
    }
}
