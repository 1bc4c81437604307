//! A finite number that is zero or positive.

use crate::shown;

/// A number that is finite and not negative: what a friction coefficient
/// or a coefficient of restitution must be, where zero means "none". NaN,
/// the infinities and negatives are refused with a message that says
/// which; [`at_most`](Self::at_most) bounds it from above.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct NonNegativeFinite(pub f64);

impl NonNegativeFinite {
    /// The number.
    #[must_use]
    pub fn get(self) -> f64 {
        self.0
    }

    /// Checks `x` (already a number); `-0` is taken as `0`.
    ///
    /// # Errors
    /// What is wrong with `x`, in words.
    pub fn new(x: f64) -> Result<Self, String> {
        if x.is_nan() {
            Err("must be a number, not NaN".to_owned())
        } else if x.is_infinite() {
            Err(format!("must be finite, not {x}"))
        } else if x < 0.0 {
            Err(format!("must be zero or positive, not {}", shown(x)))
        } else {
            Ok(Self(x.abs()))
        }
    }

    /// Checks that the number is at most `max` (`what` names the limit in
    /// the message, such as "a coefficient of restitution").
    ///
    /// # Errors
    /// The number and the limit.
    pub fn at_most(self, max: f64, what: &str) -> Result<Self, String> {
        if self.0 <= max {
            Ok(self)
        } else {
            Err(format!(
                "{} is above {}, the most {what} can be",
                shown(self.0),
                shown(max)
            ))
        }
    }
}

checked_number!(NonNegativeFinite);

#[cfg(test)]
mod tests {
    use super::NonNegativeFinite;

    #[test]
    fn zero_and_positives_pass_and_the_rest_is_refused_in_words() {
        assert_eq!("0".parse(), Ok(NonNegativeFinite(0.0)));
        assert_eq!(
            "-0".parse::<NonNegativeFinite>()
                .map(|x| x.get().is_sign_positive()),
            Ok(true)
        );
        assert_eq!(" 0.8 ".parse(), Ok(NonNegativeFinite(0.8)));
        for (text, words) in [
            ("NaN", "not NaN"),
            ("inf", "finite"),
            ("-inf", "finite"),
            ("-0.5", "zero or positive"),
            ("x", "not a number"),
        ] {
            let error = text.parse::<NonNegativeFinite>().unwrap_err();
            assert!(error.contains(words), "{text}: {error}");
        }
        let error = NonNegativeFinite(1.5)
            .at_most(1.0, "a coefficient of restitution")
            .unwrap_err();
        assert_eq!(
            error,
            "1.5 is above 1, the most a coefficient of restitution can be"
        );
        assert_eq!(
            NonNegativeFinite(1.0).at_most(1.0, ""),
            Ok(NonNegativeFinite(1.0))
        );
    }
}
