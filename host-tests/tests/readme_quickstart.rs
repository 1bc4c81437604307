//! The README's first program is the runnable quick start.
//!
//! `README.md`'s first ```rust block must be, byte for byte (up to the
//! trailing newline), `crates/rodyn/examples/quickstart.rs`, which
//! `cargo test` builds and `cargo run -p rodyn --example quickstart` runs;
//! so the program a reader copies from the README is one that compiles.

use std::path::Path;

/// The body of the first fenced block opened with ```rust, if any.
fn first_rust_block(markdown: &str) -> Option<String> {
    let mut lines = markdown.lines();
    lines.by_ref().find(|line| line.trim_end() == "```rust")?;
    let mut body = String::new();
    for line in lines {
        if line.trim_end() == "```" {
            return Some(body);
        }
        body.push_str(line);
        body.push('\n');
    }
    None
}

#[test]
fn readme_first_program_is_the_quickstart_example() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md readable");
    let example = std::fs::read_to_string(root.join("crates/rodyn/examples/quickstart.rs"))
        .expect("quickstart.rs readable");
    let block = first_rust_block(&readme).expect("README.md has a ```rust block");
    assert_eq!(
        block.trim_end(),
        example.trim_end(),
        "README.md's first ```rust block differs from crates/rodyn/examples/quickstart.rs; \
         copy the example into the README (or the README into the example)"
    );
}

#[test]
fn first_rust_block_is_found_and_closed() {
    let text = "intro\n```sh\nls\n```\n```rust\nfn main() {}\n```\nafter\n```rust\nx\n```\n";
    assert_eq!(first_rust_block(text).as_deref(), Some("fn main() {}\n"));
    assert_eq!(first_rust_block("```rust\nunclosed\n"), None);
}
