//! The number of steps of a run, bounded.

use crate::shown;

/// The number of steps of length `dt` in `duration`, rounded to the
/// nearest: at least one, at most `max_steps`. `duration_name` and
/// `dt_name` are the arguments' names as the user typed them, for the
/// messages. Both numbers are assumed positive and finite (see
/// [`PositiveFinite`](crate::PositiveFinite)).
///
/// # Errors
/// A step longer than the duration (a run that would simulate nothing),
/// or more steps than `max_steps` (a run that would not end in reasonable
/// time), with both values and the limit.
pub fn step_count(
    duration: f64,
    dt: f64,
    max_steps: usize,
    duration_name: &str,
    dt_name: &str,
) -> Result<usize, String> {
    let steps = (duration / dt).round();
    if steps.is_nan() || steps < 1.0 {
        Err(format!(
            "{dt_name} {} s is longer than {duration_name} {} s: the run would take no step",
            shown(dt),
            shown(duration)
        ))
    } else if steps > max_steps as f64 {
        Err(format!(
            "{duration_name} {} s at {dt_name} {} s is {steps:.3e} steps, above the limit of {max_steps}; \
             shorten {duration_name} or lengthen {dt_name}",
            shown(duration),
            shown(dt)
        ))
    } else {
        // In range, so the conversion is exact.
        Ok(steps as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::step_count;

    #[test]
    fn counts_rounded_steps_within_the_limit() {
        assert_eq!(
            step_count(5.0, 1e-3, 10_000, "--duration", "--dt"),
            Ok(5000)
        );
        assert_eq!(step_count(1.0, 0.3, 10, "--duration", "--dt"), Ok(3));
        assert_eq!(
            step_count(10.0, 1e-3, 10_000, "--duration", "--dt"),
            Ok(10_000)
        );
    }

    #[test]
    fn refuses_no_step_and_too_many_naming_both_arguments_and_the_limit() {
        let none = step_count(1.0, 3.0, 10, "--duration", "--dt").unwrap_err();
        assert!(
            none.contains("--dt 3 s") && none.contains("no step"),
            "{none}"
        );
        for (duration, dt) in [(1e300, 1e-3), (5.0, 5e-300), (10.001, 1e-3)] {
            let many = step_count(duration, dt, 10_000, "--duration", "--dt").unwrap_err();
            assert!(
                many.contains("limit of 10000")
                    && many.contains("--duration")
                    && many.contains("--dt"),
                "{many}"
            );
        }
    }
}
