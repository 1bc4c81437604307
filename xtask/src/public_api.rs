//! The public API of the published libraries, as a sorted list of item
//! names checked in under `xtask/public-api/`, so that `lint` fails when a
//! change removes or renames what a user may name (a semver-breaking
//! change), and shows what it adds.
//!
//! The list comes from rustdoc's JSON output (nightly only): every public
//! module, type, trait, function, constant and macro by path; each public
//! field and enum variant; each inherent method and associated constant;
//! each trait a type implements by hand (not auto traits nor blanket
//! impls); `#[non_exhaustive]` on a type. Signatures are not compared: a
//! changed argument list with the same name passes.
//!
//! `cargo xtask public-api` checks; `cargo xtask public-api --bless`
//! rewrites the lists after an intended change (a release note then says
//! what was removed) and records new items, which the check only lists.
//!
//! rustdoc's JSON is a nightly feature whose format changes: a list
//! records the format it was made from, and a check with another format,
//! or without a nightly toolchain (`lint` on a machine that has only the
//! pinned stable one), says so and compares nothing rather than failing
//! on a difference of format.

use anyhow::{bail, Context, Result};
use serde_json::{Map, Value};
use std::collections::BTreeSet;
use std::path::PathBuf;
use std::process::Command;

use crate::shell;

/// The published libraries and the features their documentation shows.
const LIBRARIES: [(&str, &str, &str); 2] = [
    ("rodyn", "rodyn", "std,nalgebra,approx"),
    ("rodyn-model", "rodyn_model", ""),
];

/// Checks each library's public items against its list, or rewrites the
/// lists with `bless`.
pub fn run(bless: bool) -> Result<()> {
    if !bless && !nightly_installed() {
        println!("public-api: skipped, no nightly toolchain (rustdoc's JSON needs one)");
        return Ok(());
    }
    for (package, krate, features) in LIBRARIES {
        let (format, now) = public_items(package, krate, features)?;
        let file = list_file(package);
        let header = format!("# rustdoc JSON format {format}");
        if bless {
            std::fs::create_dir_all(file.parent().expect("a folder"))?;
            let lines: String = now.iter().map(|l| format!("{l}\n")).collect();
            std::fs::write(&file, format!("{header}\n{lines}"))?;
            println!("public-api: wrote {} ({} items)", file.display(), now.len());
            continue;
        }
        let text = std::fs::read_to_string(&file).with_context(|| {
            format!(
                "reading {} (`cargo xtask public-api --bless` makes it)",
                file.display()
            )
        })?;
        let mut lines = text.lines();
        if lines.next() != Some(header.as_str()) {
            println!(
                "public-api: {package}: skipped, {} was made from another rustdoc JSON format \
                 than this nightly's ({format}); `--bless` with the nightly at hand remakes it",
                file.display()
            );
            continue;
        }
        let before: BTreeSet<String> = lines.map(str::to_owned).collect();
        let removed: Vec<&str> = before.difference(&now).map(String::as_str).collect();
        let added: Vec<&str> = now.difference(&before).map(String::as_str).collect();
        for item in &added {
            println!("public-api: {package}: added {item}");
        }
        if !removed.is_empty() {
            bail!(
                "{package}'s public API lost {} item(s) against {} (a breaking change):\n  {}\n\
                 if intended, `cargo xtask public-api --bless` and say so in CHANGELOG.md",
                removed.len(),
                file.display(),
                removed.join("\n  ")
            );
        }
        if added.is_empty() {
            println!("public-api: {package}: {} items, unchanged", now.len());
        } else {
            println!(
                "public-api: {package}: {} new item(s); `cargo xtask public-api --bless` records them",
                added.len()
            );
        }
    }
    Ok(())
}

/// Whether rustup has a nightly toolchain (nothing is downloaded).
fn nightly_installed() -> bool {
    Command::new("rustup")
        .args(["run", "nightly", "rustc", "--version"])
        .output()
        .is_ok_and(|out| out.status.success())
}

fn list_file(package: &str) -> PathBuf {
    shell::root()
        .join("xtask/public-api")
        .join(format!("{package}.txt"))
}

/// rustdoc's JSON of `package` (nightly, its own target folder so that the
/// stable builds are left alone), turned into item lines.
fn public_items(package: &str, krate: &str, features: &str) -> Result<(u64, BTreeSet<String>)> {
    let root = shell::root();
    let target = root.join("target/public-api");
    let mut command = Command::new("rustup");
    command
        .current_dir(&root)
        .args(["run", "nightly", "cargo", "rustdoc", "--lib", "-p", package])
        .env("CARGO_TARGET_DIR", &target);
    if !features.is_empty() {
        command.args(["--features", features]);
    }
    command.args(["--", "-Z", "unstable-options", "--output-format", "json"]);
    println!("$ {}", shell::describe(&command));
    let status = command
        .status()
        .context("running rustup (the public-API list needs the nightly toolchain)")?;
    if !status.success() {
        bail!(
            "rustdoc JSON of {package} failed; the public-API list needs a nightly toolchain \
             (`rustup toolchain install nightly`)"
        );
    }
    let path = target.join("doc").join(format!("{krate}.json"));
    let json: Value = serde_json::from_str(&std::fs::read_to_string(&path)?)?;
    let index = json["index"]
        .as_object()
        .context("rustdoc JSON without an index")?;
    let root_id = id_key(&json["root"]);
    let format = json["format_version"].as_u64().unwrap_or(0);
    let mut items = BTreeSet::new();
    walk_module(index, &root_id, krate, &mut items);
    Ok((format, items))
}

/// An id as the index's key (a number in recent formats, a string before).
fn id_key(id: &Value) -> String {
    match id {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// The item's one inner kind and its body: `("struct", {...})`.
fn inner(item: &Value) -> Option<(&str, &Value)> {
    match &item["inner"] {
        Value::Object(map) => map.iter().next().map(|(k, v)| (k.as_str(), v)),
        Value::String(kind) => Some((kind.as_str(), &Value::Null)),
        _ => None,
    }
}

fn is_non_exhaustive(item: &Value) -> bool {
    item["attrs"].to_string().contains("non_exhaustive")
}

fn ids(list: &Value) -> Vec<String> {
    list.as_array()
        .map(|a| a.iter().map(id_key).collect())
        .unwrap_or_default()
}

fn walk_module(index: &Map<String, Value>, id: &str, path: &str, out: &mut BTreeSet<String>) {
    let Some((_, module)) = index.get(id).and_then(inner) else {
        return;
    };
    for child in ids(&module["items"]) {
        let Some(item) = index.get(&child) else {
            continue;
        };
        let name = item["name"].as_str().unwrap_or("_");
        visit(index, &child, name, path, out);
    }
}

/// Item `id`, public as `path::name`: a re-export (`pub use`) counts as
/// the item it names, at the path where users find it.
fn visit(index: &Map<String, Value>, id: &str, name: &str, path: &str, out: &mut BTreeSet<String>) {
    let Some(item) = index.get(id) else {
        return;
    };
    let Some((kind, body)) = inner(item) else {
        return;
    };
    let here = format!("{path}::{name}");
    match kind {
        "module" => {
            out.insert(format!("mod {here}"));
            walk_module(index, id, &here, out);
        }
        "use" => {
            let target = id_key(&body["id"]);
            let local = index.contains_key(&target);
            if body["is_glob"].as_bool() == Some(true) {
                if local {
                    walk_module(index, &target, path, out);
                } else {
                    out.insert(format!(
                        "use {path}::* = {}",
                        body["source"].as_str().unwrap_or("?")
                    ));
                }
            } else if local {
                visit(
                    index,
                    &target,
                    body["name"].as_str().unwrap_or(name),
                    path,
                    out,
                );
            } else {
                // Another crate's item, re-exported.
                out.insert(format!(
                    "use {here} = {}",
                    body["source"].as_str().unwrap_or("?")
                ));
            }
        }
        "struct" | "enum" | "union" | "trait" => {
            out.insert(format!("{kind} {here}"));
            if is_non_exhaustive(item) {
                out.insert(format!("#[non_exhaustive] {here}"));
            }
            type_members(index, kind, body, &here, out);
        }
        _ => {
            out.insert(format!("{kind} {here}"));
        }
    }
}

/// A type's public fields, variants, inherent items and hand-written
/// trait impls.
fn type_members(
    index: &Map<String, Value>,
    kind: &str,
    body: &Value,
    here: &str,
    out: &mut BTreeSet<String>,
) {
    let mut names = |list: &Value, what: &str| {
        for id in ids(list) {
            if let Some(name) = index.get(&id).and_then(|i| i["name"].as_str()) {
                out.insert(format!("{what} {here}::{name}"));
            }
        }
    };
    match kind {
        "struct" | "union" => {
            names(&body["kind"]["plain"]["fields"], "field");
            names(&body["fields"], "field");
        }
        "enum" => names(&body["variants"], "variant"),
        "trait" => names(&body["items"], "trait item"),
        _ => {}
    }
    for impl_id in ids(&body["impls"]) {
        let Some((_, imp)) = index.get(&impl_id).and_then(inner) else {
            continue;
        };
        if imp["is_synthetic"].as_bool() == Some(true) || !imp["blanket_impl"].is_null() {
            continue;
        }
        if imp["trait"].is_null() {
            for id in ids(&imp["items"]) {
                if let Some(item) = index.get(&id) {
                    let (what, _) = inner(item).unwrap_or(("item", &Value::Null));
                    if let Some(name) = item["name"].as_str() {
                        out.insert(format!("{what} {here}::{name}"));
                    }
                }
            }
        } else {
            let t = &imp["trait"];
            let trait_name = t["path"].as_str().or(t["name"].as_str()).unwrap_or("?");
            out.insert(format!("impl {trait_name} for {here}"));
        }
    }
}
