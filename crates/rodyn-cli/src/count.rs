//! A whole number within bounds.

use core::fmt;
use core::str::FromStr;

/// A whole number from `MIN` to `MAX`: rounds, calls, collocation nodes.
/// The bounds are in the type so that the message of a refusal, and the
/// documentation of the argument, state them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Count<const MIN: usize, const MAX: usize>(pub usize);

impl<const MIN: usize, const MAX: usize> Count<MIN, MAX> {
    /// The number.
    #[must_use]
    pub fn get(self) -> usize {
        self.0
    }

    /// Checks `n`.
    ///
    /// # Errors
    /// `n` and the bounds.
    pub fn new(n: usize) -> Result<Self, String> {
        const {
            assert!(
                MIN <= MAX,
                "a count's lower bound must not exceed its upper bound"
            )
        };
        if (MIN..=MAX).contains(&n) {
            Ok(Self(n))
        } else {
            Err(Self::range_message(&n.to_string()))
        }
    }

    fn range_message(what: &str) -> String {
        format!("must be a whole number from {MIN} to {MAX}, not {what}")
    }
}

impl<const MIN: usize, const MAX: usize> FromStr for Count<MIN, MAX> {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let trimmed = s.trim();
        match trimmed.parse::<usize>() {
            Ok(n) => Self::new(n),
            // Too large for usize, negative, a fraction or not a number:
            // all are outside the range, and the message says so.
            Err(_) => Err(Self::range_message(&format!("`{trimmed}`"))),
        }
    }
}

impl<const MIN: usize, const MAX: usize> fmt::Display for Count<MIN, MAX> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

#[cfg(test)]
mod tests {
    use super::Count;

    type Rounds = Count<1, 100>;

    #[test]
    fn refuses_what_is_not_a_whole_number_in_range_and_states_the_range() {
        for text in [
            "0",
            "101",
            "-1",
            "1.5",
            "NaN",
            "inf",
            "1e300",
            "99999999999999999999999",
            "",
        ] {
            let error = text.parse::<Rounds>().unwrap_err();
            assert!(error.contains("from 1 to 100"), "{text}: {error}");
        }
    }

    #[test]
    fn keeps_the_bounds_themselves() {
        assert_eq!("1".parse::<Rounds>(), Ok(Count(1)));
        assert_eq!(" 100".parse::<Rounds>().map(Count::get), Ok(100));
    }
}
