//! The measuring binaries' arguments, checked alike in each: a time per
//! measurement, a number of rounds or calls, and the profilers' `--only`.

use rodyn_cli::{Count, PositiveFinite};

/// The longest time per measurement `--ms` takes (ms): with every model,
/// algorithm and round timed, longer would run for hours.
pub const MAX_MS: f64 = 10_000.0;

/// Rounds of a comparison (`--rounds`).
pub type Rounds = Count<1, 100>;

/// Calls of one algorithm under a profiler: a billion would run for
/// minutes uninstrumented and for hours under callgrind.
pub type Calls = Count<1, 100_000_000>;

/// The value parser of `--ms`: positive, finite, at most [`MAX_MS`].
///
/// # Errors
/// What is wrong with the number, or the limit.
pub fn milliseconds(text: &str) -> Result<f64, String> {
    let ms: PositiveFinite = text.parse()?;
    Ok(ms.at_most(MAX_MS, "ms")?.get())
}

/// `--only MODEL ALGORITHM CALLS`: one algorithm on one model, a fixed
/// number of calls, nothing printed (for profilers).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Only {
    /// One of the binary's models.
    pub model: String,
    /// One of the binary's algorithms.
    pub algorithm: String,
    /// How many calls.
    pub calls: usize,
}

impl Only {
    /// Checks the three values of `--only` against the binary's `models`
    /// and `algorithms`.
    ///
    /// # Errors
    /// A value count other than three, an unknown model or algorithm (with
    /// the known ones), or a count of calls out of range.
    pub fn parse(values: &[String], models: &[&str], algorithms: &[&str]) -> Result<Self, String> {
        let [model, algorithm, calls] = values else {
            return Err(format!(
                "--only needs MODEL ALGORITHM CALLS, got {} values",
                values.len()
            ));
        };
        let known = |what: &str, value: &str, list: &[&str]| {
            if list.contains(&value) {
                Ok(())
            } else {
                Err(format!(
                    "--only: unknown {what} `{value}`; one of {}",
                    list.join(", ")
                ))
            }
        };
        known("model", model, models)?;
        known("algorithm", algorithm, algorithms)?;
        let calls: Calls = calls.parse().map_err(|e| format!("--only: CALLS {e}"))?;
        Ok(Self {
            model: model.clone(),
            algorithm: algorithm.clone(),
            calls: calls.get(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{milliseconds, Only};

    fn strings(values: &[&str]) -> Vec<String> {
        values.iter().map(|s| (*s).to_owned()).collect()
    }

    #[test]
    fn milliseconds_are_positive_finite_and_bounded() {
        assert_eq!(milliseconds("20"), Ok(20.0));
        assert!(milliseconds("1e5")
            .unwrap_err()
            .contains("limit of 10000 ms"));
        assert!(milliseconds("NaN").unwrap_err().contains("NaN"));
        assert!(milliseconds("0").unwrap_err().contains("positive"));
    }

    #[test]
    fn only_names_what_is_wrong_and_what_is_known() {
        let (models, algorithms) = (&["ur5", "panda"][..], &["aba", "rnea"][..]);
        assert_eq!(
            Only::parse(&strings(&["ur5", "aba", "10"]), models, algorithms),
            Ok(Only {
                model: "ur5".into(),
                algorithm: "aba".into(),
                calls: 10
            })
        );
        let error = |v: &[&str]| Only::parse(&strings(v), models, algorithms).unwrap_err();
        assert!(
            error(&["hexapod", "aba", "1"]).contains("unknown model `hexapod`; one of ur5, panda")
        );
        assert!(error(&["ur5", "crba", "1"]).contains("unknown algorithm `crba`"));
        assert!(error(&["ur5", "aba", "0"]).contains("from 1 to 100000000"));
        assert!(error(&["ur5", "aba", "1e300"]).contains("from 1 to 100000000"));
        assert!(error(&["ur5"]).contains("got 1 values"));
    }
}
