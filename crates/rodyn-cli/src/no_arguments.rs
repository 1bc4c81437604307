//! Programs that take no arguments say so instead of ignoring them.

/// Refuses any command-line argument: a program without options that
/// ran anyway would let `--duration 10` look as if it had been obeyed.
/// `program` and `what_it_does` go into the message.
///
/// # Errors
/// The arguments given, and that the program takes none.
pub fn no_arguments(program: &str, what_it_does: &str) -> Result<(), String> {
    refuse_any(program, what_it_does, std::env::args().skip(1))
}

fn refuse_any(
    program: &str,
    what_it_does: &str,
    args: impl Iterator<Item = String>,
) -> Result<(), String> {
    let given: Vec<String> = args.collect();
    if given.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "{program} takes no arguments (it {what_it_does}); got `{}`",
            given.join(" ")
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::refuse_any;

    #[test]
    fn any_argument_is_refused_and_repeated() {
        let error = refuse_any(
            "plots",
            "writes the figures",
            ["--duration", "10"].map(String::from).into_iter(),
        )
        .unwrap_err();
        assert_eq!(
            error,
            "plots takes no arguments (it writes the figures); got `--duration 10`"
        );
        assert_eq!(refuse_any("plots", "", std::iter::empty()), Ok(()));
    }
}
