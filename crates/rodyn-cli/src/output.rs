//! Outputs checked before the work that fills them.

use std::fs::OpenOptions;
use std::path::Path;

/// Creates the directory `dir` (and its parents) and checks that a file
/// can be written in it, so that a run fails at once rather than after
/// its computation.
///
/// # Errors
/// The directory and the system's reason.
pub fn writable_dir(dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("cannot create the directory {}: {e}", dir.display()))?;
    let trial = dir.join(format!(".rodyn-write-check-{}", std::process::id()));
    OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&trial)
        .map_err(|e| format!("cannot write in {}: {e}", dir.display()))?;
    // The check's own file: failing to remove it leaves an empty file.
    let _ = std::fs::remove_file(&trial);
    Ok(())
}

/// Checks that `file` can be written: its directory exists and the file
/// opens for writing. An existing file is left as it is; a new one is
/// removed again.
///
/// # Errors
/// The file and the system's reason.
pub fn writable_file(file: &Path) -> Result<(), String> {
    let existed = file.exists();
    if file.is_dir() {
        return Err(format!("{} is a directory, not a file", file.display()));
    }
    OpenOptions::new()
        .append(true)
        .create(true)
        .open(file)
        .map_err(|e| format!("cannot write {}: {e}", file.display()))?;
    if !existed {
        let _ = std::fs::remove_file(file);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{writable_dir, writable_file};

    #[test]
    fn a_path_under_a_file_is_refused_with_its_name() {
        let base = std::env::temp_dir().join(format!("rodyn-cli-output-{}", std::process::id()));
        std::fs::create_dir_all(&base).unwrap();
        let file = base.join("plain-file");
        std::fs::write(&file, "x").unwrap();
        let under = file.join("out");
        let error = writable_dir(&under).unwrap_err();
        assert!(error.contains(&under.display().to_string()), "{error}");
        let error = writable_file(&under.join("a.svg")).unwrap_err();
        assert!(error.contains("a.svg"), "{error}");
        assert!(writable_file(&base).unwrap_err().contains("is a directory"));

        writable_dir(&base.join("new/deeper")).unwrap();
        assert!(base.join("new/deeper").is_dir());
        assert_eq!(
            std::fs::read_dir(base.join("new/deeper")).unwrap().count(),
            0
        );
        writable_file(&base.join("fresh.svg")).unwrap();
        assert!(!base.join("fresh.svg").exists());
        writable_file(&file).unwrap();
        assert_eq!(std::fs::read_to_string(&file).unwrap(), "x");
        std::fs::remove_dir_all(&base).unwrap();
    }
}
