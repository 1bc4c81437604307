//! `rodyn-drive-plots` takes no arguments: it refuses any rather than
//! ignore them (run without, it rewrites the documentation's figures, so
//! that run is left to its users).

use rodyn_cli::probe::assert_refused;
use std::path::Path;

#[test]
fn arguments_are_refused() {
    let exe = Path::new(env!("CARGO_BIN_EXE_rodyn-drive-plots"));
    for args in [&["--duration", "10"][..], &["out/"], &["--help"]] {
        assert_refused(exe, args, "takes no arguments");
    }
}
