//! Statistics for checks that never hide a NaN: every function fails on an empty input or a
//! value that is not a number, naming where it was, instead of folding it away (as
//! `f64::max` would).

pub use crate::model::StatsError;

fn checked(v: &[f64]) -> Result<&[f64], StatsError> {
    if v.is_empty() {
        return Err(StatsError::Empty);
    }
    match v.iter().position(|x| x.is_nan()) {
        Some(index) => Err(StatsError::NotANumber { index }),
        None => Ok(v),
    }
}

/// Largest value.
///
/// ```
/// # use attlab::analysis::stats::max;
/// assert_eq!(max(&[1.0, 3.0, 2.0]), Ok(3.0));
/// assert!(max(&[1.0, f64::NAN]).is_err());
/// assert!(max(&[]).is_err());
/// ```
pub fn max(v: &[f64]) -> Result<f64, StatsError> {
    Ok(checked(v)?
        .iter()
        .copied()
        .fold(f64::NEG_INFINITY, f64::max))
}

/// Smallest value.
pub fn min(v: &[f64]) -> Result<f64, StatsError> {
    Ok(checked(v)?.iter().copied().fold(f64::INFINITY, f64::min))
}

/// Largest absolute value.
///
/// ```
/// # use attlab::analysis::stats::max_abs;
/// assert_eq!(max_abs(&[1.0, -3.0]), Ok(3.0));
/// assert!(max_abs(&[f64::NAN, 1.0]).is_err());
/// ```
pub fn max_abs(v: &[f64]) -> Result<f64, StatsError> {
    Ok(checked(v)?.iter().fold(0.0, |m: f64, x| m.max(x.abs())))
}

/// Arithmetic mean.
pub fn mean(v: &[f64]) -> Result<f64, StatsError> {
    let v = checked(v)?;
    Ok(v.iter().sum::<f64>() / v.len() as f64)
}

/// Root mean square.
///
/// ```
/// # use attlab::analysis::stats::rms;
/// assert_eq!(rms(&[3.0, -3.0]), Ok(3.0));
/// ```
pub fn rms(v: &[f64]) -> Result<f64, StatsError> {
    let v = checked(v)?;
    Ok((v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt())
}

/// Standard deviation about the mean (population form).
pub fn std_dev(v: &[f64]) -> Result<f64, StatsError> {
    let m = mean(v)?;
    Ok((v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / v.len() as f64).sqrt())
}

/// Median.
///
/// ```
/// # use attlab::analysis::stats::median;
/// assert_eq!(median(&[3.0, 1.0, 2.0]), Ok(2.0));
/// assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Ok(2.5));
/// ```
pub fn median(v: &[f64]) -> Result<f64, StatsError> {
    let mut s = checked(v)?.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    Ok(if n % 2 == 1 {
        s[n / 2]
    } else {
        0.5 * (s[n / 2 - 1] + s[n / 2])
    })
}

/// Fraction of values satisfying `pred`.
pub fn fraction(v: &[f64], pred: impl Fn(f64) -> bool) -> Result<f64, StatsError> {
    let v = checked(v)?;
    Ok(v.iter().filter(|x| pred(**x)).count() as f64 / v.len() as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nan_is_reported_where_it_is() {
        assert_eq!(
            rms(&[1.0, 2.0, f64::NAN]),
            Err(StatsError::NotANumber { index: 2 })
        );
        assert_eq!(median(&[]), Err(StatsError::Empty));
        assert_eq!(fraction(&[1.0, -1.0], |x| x > 0.0), Ok(0.5));
    }
}
