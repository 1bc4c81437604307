//! Every file in `tests/bad/` must fail to load with the position and the
//! sentence written in its first line (`expect: line:column: message`).

use rodyn_model::{load, LoadOptions, Severity};
use std::path::Path;

#[test]
fn every_bad_file_fails_where_and_how_it_says() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad");
    let mut files = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect::<Vec<_>>();
    files.sort();
    assert!(files.len() >= 15, "only {} bad files", files.len());
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let first = text.lines().next().unwrap();
        let expected = first
            .split_once("expect: ")
            .map(|(_, e)| e.trim_end_matches("-->").trim())
            .unwrap_or_else(|| panic!("{}: no `expect:` line", file.display()));
        let diagnostic = match load(file, LoadOptions::default()) {
            Ok(_) => panic!("{} loaded, but should fail with {expected}", file.display()),
            Err(d) => d,
        };
        assert_eq!(diagnostic.severity, Severity::Error);
        assert_eq!(diagnostic.location.file, *file);
        let got = format!(
            "{}:{}: {}",
            diagnostic.location.line, diagnostic.location.column, diagnostic.message
        );
        assert!(
            got.starts_with(expected),
            "{}:\n  expected {expected}\n  got      {got}",
            file.display()
        );
        // The printed form is what an editor or CI log links to.
        let printed = diagnostic.to_string();
        assert!(printed.starts_with(&format!(
            "{}:{}",
            file.display(),
            got.split(": ").next().unwrap()
        )));
        assert!(printed.contains(": error: "));
    }
}

#[test]
fn warnings_name_what_was_ignored() {
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../models/urdf/panda.urdf");
    let model = load(&urdf, LoadOptions::default()).unwrap();
    let messages = model
        .warnings
        .iter()
        .map(|w| w.message.as_str())
        .collect::<Vec<_>>();
    assert!(
        messages
            .iter()
            .any(|m| m.contains("<limit>") && m.contains("7 times")),
        "{messages:?}"
    );
    assert!(model
        .warnings
        .iter()
        .all(|w| w.severity == Severity::Warning));
}
