//! A positive, finite, normal number.

use crate::shown;

/// A number that is positive, finite and normal: what a step, a duration
/// or a size must be. NaN, the infinities, zero, negatives and subnormals
/// (below about 2.2e-308, where a division by them overflows) are refused
/// with a message that says which.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct PositiveFinite(pub f64);

impl PositiveFinite {
    /// The number.
    #[must_use]
    pub fn get(self) -> f64 {
        self.0
    }

    /// Checks `x` (already a number).
    ///
    /// # Errors
    /// What is wrong with `x`, in words.
    pub fn new(x: f64) -> Result<Self, String> {
        if x.is_nan() {
            Err("must be a number, not NaN".to_owned())
        } else if x.is_infinite() {
            Err(format!("must be finite, not {x}"))
        } else if x <= 0.0 {
            Err(format!("must be positive, not {}", shown(x)))
        } else if !x.is_normal() {
            Err(format!(
                "{x:e} is too small to compute with (below {:e})",
                f64::MIN_POSITIVE
            ))
        } else {
            Ok(Self(x))
        }
    }

    /// Checks that the number is at most `max`; `unit` follows the limit
    /// in the message (`"s"`, `"px"`, or empty).
    ///
    /// # Errors
    /// The number and the limit.
    pub fn at_most(self, max: f64, unit: &str) -> Result<Self, String> {
        if self.0 <= max {
            Ok(self)
        } else {
            let unit = if unit.is_empty() {
                String::new()
            } else {
                format!(" {unit}")
            };
            Err(format!(
                "{} is above the limit of {}{unit}",
                shown(self.0),
                shown(max)
            ))
        }
    }
}

checked_number!(PositiveFinite);

#[cfg(test)]
mod tests {
    use super::PositiveFinite;

    #[test]
    fn refuses_every_kind_of_bad_number_and_says_which() {
        for (text, words) in [
            ("NaN", "not NaN"),
            ("inf", "finite"),
            ("-inf", "finite"),
            ("0", "positive"),
            ("-0", "positive"),
            ("-1e-3", "positive"),
            ("5e-324", "too small"),
            ("1e-310", "too small"),
            ("one", "not a number"),
            ("", "not a number"),
        ] {
            let error = text.parse::<PositiveFinite>().unwrap_err();
            assert!(error.contains(words), "{text}: {error}");
        }
    }

    #[test]
    fn keeps_good_numbers_exactly() {
        for x in [f64::MIN_POSITIVE, 1e-3, 5.0, 1e300] {
            assert_eq!(
                format!("{x:e}").parse::<PositiveFinite>(),
                Ok(PositiveFinite(x))
            );
        }
        assert_eq!(
            " 2.5 ".parse::<PositiveFinite>().map(PositiveFinite::get),
            Ok(2.5)
        );
    }

    #[test]
    fn a_limit_is_named_with_its_unit() {
        let error = PositiveFinite(2e4).at_most(1e4, "px").unwrap_err();
        assert_eq!(error, "20000 is above the limit of 10000 px");
        assert_eq!(
            PositiveFinite(1e4).at_most(1e4, "px"),
            Ok(PositiveFinite(1e4))
        );
    }
}
