//! Rust identifiers from the names in model files.

use crate::diagnostic::{Diagnostic, Location, Result};
use std::collections::HashMap;

/// `panda_link1` → `PANDA_LINK1`, `left-knee` → `LEFT_KNEE`, `1st` → `_1ST`.
#[must_use]
pub fn constant_name(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .collect();
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, '_');
    }
    out
}

/// `Panda Arm` → `panda_arm`; a keyword gets a trailing underscore.
#[must_use]
pub fn module_name(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect();
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) {
        out.insert(0, '_');
    }
    const KEYWORDS: &[&str] = &[
        "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum",
        "extern", "false", "fn", "for", "if", "impl", "in", "let", "loop", "match", "mod", "move",
        "mut", "pub", "ref", "return", "self", "static", "struct", "super", "trait", "true",
        "type", "unsafe", "use", "where", "while", "abstract", "become", "box", "do", "final",
        "macro", "override", "priv", "try", "typeof", "unsized", "virtual", "yield",
    ];
    if KEYWORDS.contains(&out.as_str()) {
        out.push('_');
    }
    out
}

/// Checks that distinct names in one namespace stay distinct as constants.
///
/// # Errors
/// A diagnostic at the second of two names that map to the same constant.
pub fn check_distinct<'a>(
    namespace: &str,
    names: impl IntoIterator<Item = (&'a str, &'a Location)>,
) -> Result<()> {
    let mut seen: HashMap<String, &str> = HashMap::new();
    for (name, location) in names {
        if let Some(first) = seen.insert(constant_name(name), name) {
            let why = if first == name {
                format!("two {namespace}s are named `{name}`")
            } else {
                format!("the {namespace} names `{first}` and `{name}` both become the Rust constant `{}`; rename one", constant_name(name))
            };
            return Err(Diagnostic::error(location.clone(), why));
        }
    }
    Ok(())
}
