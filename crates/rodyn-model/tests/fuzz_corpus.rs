//! The fuzz corpus (`fuzz/corpus/`, the seeds of the cargo-fuzz targets and
//! the regression cases of the reliability review) as a plain test: every
//! file loads or gives a diagnostic, the generated Rust of those that load
//! is produced or refused with a diagnostic, no input panics, and no name
//! reaches the generated source outside a comment.

use rodyn_model::codegen::generate;
use rodyn_model::{load, LoadOptions};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

#[test]
fn every_corpus_file_is_handled_without_a_panic() {
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus");
    let mut files = 0;
    let mut loaded = 0;
    for target in ["load_urdf", "load_toml"] {
        for entry in std::fs::read_dir(corpus.join(target)).unwrap() {
            let path = entry.unwrap().path();
            files += 1;
            let outcome = catch_unwind(AssertUnwindSafe(|| {
                let model = load(&path, LoadOptions::default()).ok()?;
                Some(generate(&model, "fuzzed", &path.display().to_string()))
            }));
            match outcome {
                Err(_) => panic!("{} panicked", path.display()),
                Ok(Some(Ok(source))) => {
                    loaded += 1;
                    for line in source.lines() {
                        if line.contains("static INJECTED:") {
                            // A comment, or an escaped string literal.
                            let escaped = line.contains(r#"static INJECTED: &str = \"x\""#);
                            assert!(
                                line.trim_start().starts_with("//") || escaped,
                                "{}: {line}",
                                path.display()
                            );
                        }
                    }
                }
                Ok(_) => {}
            }
        }
    }
    assert!(files >= 40, "{files} corpus files");
    assert!(loaded >= 8, "only {loaded} corpus files loaded");
}
