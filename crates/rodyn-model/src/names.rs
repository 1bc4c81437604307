//! Rust identifiers from the names in model files.

use crate::diagnostic::{Diagnostic, Location, Result};
use std::collections::HashMap;

/// `panda_link1` → `PANDA_LINK1`, `left-knee` → `LEFT_KNEE`, `1st` → `_1ST`;
/// a name with no ASCII letter or digit (`"é"`, `""`) → `_U_E9`, `_EMPTY`,
/// since `_` alone is not a name Rust accepts.
#[must_use]
pub fn constant_name(name: &str) -> String {
    if !name.chars().any(|c| c.is_ascii_alphanumeric()) {
        return code_point_name(name).to_ascii_uppercase();
    }
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

/// A stand-in for a name without ASCII letters or digits: its code points
/// in hexadecimal (`"é"` → `_u_e9`), or `_empty`.
fn code_point_name(name: &str) -> String {
    if name.is_empty() {
        return "_empty".to_owned();
    }
    let points: Vec<String> = name
        .chars()
        .map(|c| format!("{:x}", u32::from(c)))
        .collect();
    format!("_u_{}", points.join("_"))
}

/// Constants a generated module defines itself as `<NAME>_F64` and
/// `<NAME>_F32`, which a drive's constants of the same form must not
/// repeat.
pub const RESERVED_CONSTANTS: &[&str] =
    &["MODEL", "ENDPOINTS", "CONTACTS", "CONTACT_POINTS", "FRAMES"];

/// Checks that no name becomes one of the module's own constants
/// ([`RESERVED_CONSTANTS`]).
///
/// # Errors
/// A diagnostic at the first such name.
pub fn check_not_reserved<'a>(
    namespace: &str,
    names: impl IntoIterator<Item = (&'a str, &'a Location)>,
) -> Result<()> {
    for (name, location) in names {
        let constant = constant_name(name);
        if RESERVED_CONSTANTS.contains(&constant.as_str()) {
            return Err(Diagnostic::error(
                location.clone(),
                format!(
                    "the {namespace} name `{name}` becomes `{constant}_F64`, which the generated \
                     module uses for its own {}; rename it",
                    constant.to_ascii_lowercase().replace('_', " ")
                ),
            ));
        }
    }
    Ok(())
}

/// `Panda Arm` → `panda_arm`; a keyword gets a trailing underscore; a name
/// with no ASCII letter or digit → `_u_<hex code points>` or `_empty`.
#[must_use]
pub fn module_name(name: &str) -> String {
    if !name.chars().any(|c| c.is_ascii_alphanumeric()) {
        return code_point_name(name);
    }
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

/// Distinct constants for `names`, in order: [`constant_name`] of each, and
/// for a name whose constant an earlier name already took, that constant
/// with the first free suffix `_2`, `_3`, ... (`a.b` and `a_b` →
/// `A_B`, `A_B_2`). For a namespace whose names the file does not keep
/// distinct after sanitising, such as the frames (a moving link and a
/// merged link), where refusing the file would be unhelpful.
#[must_use]
pub fn unique_constant_names<'a>(names: impl IntoIterator<Item = &'a str>) -> Vec<String> {
    let names: Vec<String> = names.into_iter().map(constant_name).collect();
    let mut taken: std::collections::HashSet<String> = names.iter().cloned().collect();
    let mut first: std::collections::HashSet<&str> = std::collections::HashSet::new();
    let mut out = Vec::with_capacity(names.len());
    for name in &names {
        if first.insert(name.as_str()) {
            out.push(name.clone());
            continue;
        }
        let mut k = 2_usize;
        let unique = loop {
            let candidate = format!("{name}_{k}");
            if !taken.contains(&candidate) {
                break candidate;
            }
            k += 1;
        };
        taken.insert(unique.clone());
        out.push(unique);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::unique_constant_names;

    #[test]
    fn near_collisions_get_suffixes_that_collide_with_nothing() {
        let names = unique_constant_names(["a.b", "a_b", "A_B_2", "a-b", "c"]);
        assert_eq!(names, ["A_B", "A_B_3", "A_B_2", "A_B_4", "C"]);
    }
}
