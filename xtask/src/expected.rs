//! Comparing a firmware log with its checked-in expected output.
//!
//! Lines must match in order. Within a line, tokens (split at whitespace and
//! at `[](),=:`) must be equal, except that
//! * an expected `*` matches any token (for numbers that are reported, not
//!   checked, such as instruction counts), and
//! * two numbers match when they agree to a relative 1e-3 (plus 1e-6
//!   absolute): a change in the order of f32 operations inside rodyn moves
//!   the last digits of a simulation without changing what it shows.

/// Relative tolerance between numbers.
const RELATIVE: f64 = 1e-3;
/// Absolute tolerance between numbers.
const ABSOLUTE: f64 = 1e-6;

fn tokens(line: &str) -> Vec<&str> {
    line.split(|c: char| c.is_whitespace() || "[](),=:".contains(c))
        .filter(|t| !t.is_empty())
        .collect()
}

fn tokens_match(expected: &str, actual: &str) -> bool {
    if expected == "*" || expected == actual {
        return true;
    }
    match (expected.parse::<f64>(), actual.parse::<f64>()) {
        (Ok(e), Ok(a)) => (e - a).abs() <= RELATIVE * e.abs().max(a.abs()) + ABSOLUTE,
        _ => false,
    }
}

fn lines_match(expected: &str, actual: &str) -> bool {
    let (e, a) = (tokens(expected), tokens(actual));
    e.len() == a.len() && e.iter().zip(&a).all(|(e, a)| tokens_match(e, a))
}

/// `Ok` when `actual` matches `expected`; otherwise the first difference.
pub fn compare(expected: &str, actual: &[String]) -> Result<(), String> {
    let expected: Vec<&str> = expected.lines().collect();
    for (n, (e, a)) in expected.iter().zip(actual).enumerate() {
        if !lines_match(e, a) {
            return Err(format!("line {}:\n  expected: {e}\n  actual:   {a}", n + 1));
        }
    }
    if expected.len() != actual.len() {
        return Err(format!(
            "expected {} lines, got {}; first extra or missing line: {}",
            expected.len(),
            actual.len(),
            expected
                .get(actual.len())
                .copied()
                .or_else(|| actual.get(expected.len()).map(String::as_str))
                .unwrap_or("")
        ));
    }
    Ok(())
}

/// The new expected text: `actual`, with the `*` wildcards of the old
/// expected line kept wherever that line has the same number of tokens.
pub fn bless(old: &str, actual: &[String]) -> String {
    let old: Vec<&str> = old.lines().collect();
    let mut text = String::new();
    for (n, line) in actual.iter().enumerate() {
        let kept = old.get(n).and_then(|o| keep_wildcards(o, line));
        text.push_str(kept.as_deref().unwrap_or(line));
        text.push('\n');
    }
    text
}

fn keep_wildcards(old: &str, line: &str) -> Option<String> {
    let (o, a) = (tokens(old), tokens(line));
    if o.len() != a.len() || !o.contains(&"*") {
        return None;
    }
    // Rebuild the line, replacing the wildcard positions token by token.
    let mut out = String::new();
    let mut rest = line;
    for (old_token, token) in o.iter().zip(&a) {
        let at = rest.find(token)?;
        out.push_str(&rest[..at]);
        out.push_str(if *old_token == "*" { "*" } else { token });
        rest = &rest[at + token.len()..];
    }
    out.push_str(rest);
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_match_within_tolerance_and_wildcards_match_anything() {
        let actual = vec!["q = [1.0001, 2] cost 123".to_string()];
        assert!(compare("q = [1.0, 2] cost *\n", &actual).is_ok());
        assert!(compare("q = [1.01, 2] cost *\n", &actual).is_err());
        assert!(compare("q = [1.0, 2] cost 124\n", &actual).is_err());
        assert!(compare("q = [1.0, 2] cost *\nmore\n", &actual).is_err());
    }

    #[test]
    fn bless_keeps_wildcards() {
        let actual = vec!["rnea min=812 max=830".to_string(), "new 3".to_string()];
        let text = bless("rnea min=* max=*\nold 2\n", &actual);
        assert_eq!(text, "rnea min=* max=*\nnew 3\n");
    }
}
