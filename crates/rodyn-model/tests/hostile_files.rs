//! Files that used to break the build rather than the model: deep nesting
//! (a stack overflow in the XML parser), device files as includes (memory
//! exhausted, or a build blocked on standard input).

use rodyn_model::{load, LoadOptions, Severity};
use std::path::PathBuf;

fn write(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rodyn-model-hostile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn deep_nesting_is_a_diagnostic_not_a_stack_overflow() {
    let depth = 1500;
    let text = format!(
        "<robot name=\"deep\">\n<link name=\"a\"/>\n{}{}</robot>\n",
        "<x>".repeat(depth),
        "</x>".repeat(depth)
    );
    let path = write("deep.urdf", &text);
    let error = load(&path, LoadOptions::default()).unwrap_err();
    assert_eq!(error.severity, Severity::Error);
    assert!(
        error.message.contains("nested more than 64 levels"),
        "{error}"
    );
    assert_eq!(error.location.line, 3);
    // The robot element is level 1, so the 64th `<x>` is the first past
    // the limit.
    assert_eq!(error.location.column, 1 + 3 * 63);
}

#[test]
fn nesting_inside_comments_and_quotes_does_not_count() {
    let text = format!(
        "<robot name=\"a > b\">\n<!-- {} -->\n<link name=\"a\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n<link name=\"b\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n<joint name=\"j\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/><axis xyz=\"0 0 1\"/></joint>\n</robot>\n",
        "<x>".repeat(200)
    );
    let path = write("comments.urdf", &text);
    load(&path, LoadOptions::default()).unwrap();
}

#[test]
fn device_files_are_not_read() {
    for device in ["/dev/zero", "/dev/stdin"] {
        let text = format!("[model]\nname = \"dev\"\ninclude = \"{device}\"\n");
        let path = write("device.toml", &text);
        let error = load(&path, LoadOptions::default()).unwrap_err();
        assert!(
            error.message.contains("not a regular file"),
            "{device}: {error}"
        );
        assert_eq!(
            (error.location.line, error.location.column),
            (3, 11),
            "{device}: {error}"
        );
    }
    let error = load(std::path::Path::new("/dev/zero"), LoadOptions::default()).unwrap_err();
    assert!(error.message.contains("not a regular file"), "{error}");
}

/// A chain URDF of `n` links.
fn chain(n: usize) -> String {
    let link = |i: usize| {
        format!("<link name=\"l{i}\"><inertial><mass value=\"1\"/><inertia ixx=\"0.1\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n")
    };
    let mut text = String::from("<robot name=\"chain\">\n");
    text += &link(0);
    for i in 1..=n {
        text += &link(i);
        text += &format!("<joint name=\"j{i}\" type=\"continuous\"><parent link=\"l{}\"/><child link=\"l{i}\"/><origin xyz=\"0 0 0.1\"/><axis xyz=\"0 0 1\"/></joint>\n", i - 1);
    }
    text + "</robot>\n"
}

/// Loading grows linearly with the link count: four times the links take
/// well under eight times as long (sixteen when it was quadratic, from a
/// scan of the file for each link's line number and a walk to the root
/// from each link). Timed as a ratio of two sizes in one run, the best of
/// three each, so a slow machine does not matter.
#[test]
fn loading_is_linear_in_the_link_count() {
    let time = |n: usize| {
        let path = write(&format!("chain{n}.urdf"), &chain(n));
        (0..3)
            .map(|_| {
                let start = std::time::Instant::now();
                let model = load(&path, LoadOptions::default()).unwrap();
                assert_eq!(model.bodies.len(), n);
                start.elapsed().as_secs_f64()
            })
            .fold(f64::INFINITY, f64::min)
    };
    let (small, large) = (time(1000), time(4000));
    assert!(
        large / small < 8.0,
        "1,000 links {small:.3} s, 4,000 links {large:.3} s"
    );
}
