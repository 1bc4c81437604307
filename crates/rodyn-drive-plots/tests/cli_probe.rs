//! `rodyn-drive-plots` takes `--out DIR` only: it refuses anything else
//! rather than ignore it, and an output it cannot write before it works
//! (run without arguments, it rewrites the documentation's figures, so
//! that run is left to its users and to `cargo xtask docs`).

use rodyn_cli::probe::assert_refused;
use std::path::Path;

const USAGE: &str = "usage: rodyn-drive-plots [--out DIR]";

#[test]
fn other_arguments_and_unwritable_outputs_are_refused() {
    let exe = Path::new(env!("CARGO_BIN_EXE_rodyn-drive-plots"));
    for args in [
        &["--duration", "10"][..],
        &["out/"],
        &["--help"],
        &["--out"],
    ] {
        assert_refused(exe, args, USAGE);
    }
    let dir = std::env::temp_dir().join(format!("rodyn-drive-plots-probe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let plain = dir.join("a-file");
    std::fs::write(&plain, "not a directory").unwrap();
    let unwritable = plain.join("out");
    let outcome = assert_refused(exe, &["--out", unwritable.to_str().unwrap()], "a-file");
    assert!(!outcome.stderr.contains("panicked"), "{}", outcome.stderr);
    let _ = std::fs::remove_dir_all(&dir);
}
