//! Warnings a user can silence per kind (`LoadOptions::silence`, `silence`
//! in a rodyn file's `[model]`, the CLI's `--silence`), each kind printed
//! once per file with its name and a count of the others.

use rodyn_model::{load, LoadOptions, Severity, WarningKind, WarningKinds};
use std::path::PathBuf;
use std::process::Command;

fn write(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rodyn-model-kinds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// Two revolute joints with `<limit>` and a `<mimic>`, three massless
/// sensor links with tensors fixed to the arm.
fn urdf() -> String {
    let mut body = String::from(
        "<robot name=\"kinds\">\n<link name=\"base\"/>\n\
         <link name=\"arm\"><inertial><mass value=\"1\"/><inertia ixx=\"0.1\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n\
         <link name=\"forearm\"><inertial><mass value=\"1\"/><inertia ixx=\"0.1\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n\
         <joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/><axis xyz=\"0 0 1\"/><limit effort=\"1\" velocity=\"1\"/></joint>\n\
         <joint name=\"elbow\" type=\"revolute\"><parent link=\"arm\"/><child link=\"forearm\"/><axis xyz=\"0 0 1\"/><limit effort=\"1\" velocity=\"1\"/><mimic joint=\"shoulder\"/></joint>\n",
    );
    for k in 0..3 {
        body.push_str(&format!(
            "<link name=\"sensor{k}\"><inertial><mass value=\"0\"/><inertia ixx=\"1e-6\" iyy=\"1e-6\" izz=\"1e-6\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n\
             <joint name=\"mount{k}\" type=\"fixed\"><parent link=\"arm\"/><child link=\"sensor{k}\"/></joint>\n"
        ));
    }
    body + "</robot>\n"
}

fn messages(options: LoadOptions) -> Vec<String> {
    // Tests run in parallel: one file per call.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let path = write(&format!("kinds{n}.urdf"), &urdf());
    load(&path, options)
        .unwrap_or_else(|e| panic!("{e}"))
        .warnings
        .iter()
        .filter(|w| w.severity == Severity::Warning)
        .map(ToString::to_string)
        .collect()
}

#[test]
fn each_kind_is_reported_once_per_file_with_its_name() {
    let all = messages(LoadOptions::default());
    let massless: Vec<_> = all.iter().filter(|m| m.contains("mass 0")).collect();
    assert_eq!(massless.len(), 1, "{all:#?}");
    assert!(
        massless[0].contains("sensor0")
            && massless[0].contains("2 more warnings of this kind in this file")
            && massless[0].ends_with("[massless-tensor]"),
        "{}",
        massless[0]
    );
    let limits: Vec<_> = all.iter().filter(|m| m.contains("<limit>")).collect();
    assert_eq!(limits.len(), 1, "{all:#?}");
    assert!(limits[0].contains("(2 times in this file) [limit]"));
    assert!(all
        .iter()
        .any(|m| m.contains("MIMICS and *_mimic functions") && m.ends_with("[mimic]")));
}

#[test]
fn silenced_kinds_are_not_reported_nor_refused_in_strict_mode() {
    let silence = WarningKinds::NONE
        .with(WarningKind::Limit)
        .with(WarningKind::MasslessTensor);
    let left = messages(LoadOptions::new().with_silence(silence));
    assert_eq!(left.len(), 1, "{left:#?}");
    assert!(left[0].ends_with("[mimic]"));
    // Strict mode refuses the massless tensors unless they are silenced.
    let path = write("kinds_strict.urdf", &urdf());
    let strict = LoadOptions::new().with_strict(true);
    assert!(load(&path, strict).is_err());
    load(&path, strict.with_silence(silence)).unwrap();
    assert!(messages(LoadOptions::new().with_silence(WarningKinds::ALL)).is_empty());
}

#[test]
fn a_rodyn_file_silences_its_included_urdfs_warnings() {
    write("kinds_included.urdf", &urdf());
    let toml = "[model]\nname = \"kinds\"\ninclude = \"kinds_included.urdf\"\nsilence = [\"limit\", \"mimic\"]\n";
    let path = write("kinds.toml", toml);
    let model = load(&path, LoadOptions::default()).unwrap();
    let kinds: Vec<_> = model.warnings.iter().map(|w| w.kind).collect();
    assert_eq!(kinds, [Some(WarningKind::MasslessTensor)]);
    // A name that is no kind is an error at its place, listing the kinds.
    let bad = write(
        "kinds_bad.toml",
        "[model]\nname = \"kinds\"\ninclude = \"kinds_included.urdf\"\nsilence = [\"limit\", \"limits\"]\n",
    );
    let error = load(&bad, LoadOptions::default()).unwrap_err();
    assert_eq!((error.location.line, error.location.column), (4, 21));
    assert!(
        error.message.contains("`limits` is no kind of warning")
            && error.message.contains("fixed-root-inertia"),
        "{error}"
    );
}

#[test]
fn the_cli_silences_kinds() {
    let path = write("kinds_cli.urdf", &urdf());
    let run = |extra: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_rodyn-model"))
            .arg("check")
            .arg(&path)
            .args(extra)
            .output()
            .unwrap()
    };
    let all = run(&[]);
    assert!(all.status.success());
    let stderr = String::from_utf8_lossy(&all.stderr);
    assert_eq!(stderr.lines().count(), 3, "{stderr}");
    let quiet = run(&["--silence", "limit,massless-tensor", "--silence", "mimic"]);
    assert!(quiet.status.success());
    assert_eq!(String::from_utf8_lossy(&quiet.stderr), "");
    let bad = run(&["--silence", "limitz"]);
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--silence: `limitz` is no kind"));
}

#[test]
fn a_mimic_that_cannot_be_coupled_is_a_warning() {
    let text = urdf().replace("<mimic joint=\"shoulder\"/>", "<mimic joint=\"nowhere\"/>");
    let path = write("kinds_mimic.urdf", &text);
    let model = load(&path, LoadOptions::default()).unwrap();
    assert!(model.mimics.is_empty());
    assert!(model
        .warnings
        .iter()
        .any(|w| w.kind == Some(WarningKind::Mimic)
            && w.message
                .contains("joint `elbow` mimics `nowhere`, which is not a moving joint")));
    // Coupled when the leader exists.
    let model = load(
        &write("kinds_mimic_ok.urdf", &urdf()),
        LoadOptions::default(),
    )
    .unwrap();
    assert_eq!((model.mimics[0].follower, model.mimics[0].leader), (1, 0));
}
