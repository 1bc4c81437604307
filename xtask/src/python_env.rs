//! The Python environment the test command needs: Pinocchio's bindings
//! (the reference), example-robot-data (robots with meshes), numpy,
//! pytest, matplotlib and maturin, in one venv under the target directory.
//!
//! Made on first use and kept; a venv whose recorded requirements differ
//! from [`REQUIREMENTS`] is brought up to date by pip. Nothing outside the
//! target directory is touched.

use crate::{setup, shell};
use anyhow::{bail, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Pinned so that the reference is the same everywhere: Pinocchio 4.1 is
/// the version the fixtures in `host-tests/` were written with.
pub const REQUIREMENTS: &[&str] = &[
    "pin==4.1.0",
    "example-robot-data==6.0.0",
    "numpy",
    "pytest",
    "matplotlib",
    "maturin>=1.7,<2",
];

/// A Python virtual environment.
pub struct Venv {
    root: PathBuf,
}

impl Venv {
    /// The venv's interpreter.
    pub fn python(&self) -> PathBuf {
        self.root.join("bin/python")
    }

    /// A command running the venv's interpreter, with the venv active
    /// (`VIRTUAL_ENV` and `PATH`, as maturin expects).
    pub fn command(&self) -> Command {
        let mut command = Command::new(self.python());
        let path = std::env::var_os("PATH").unwrap_or_default();
        let mut paths = vec![self.root.join("bin")];
        paths.extend(std::env::split_paths(&path));
        command.env("VIRTUAL_ENV", &self.root).env(
            "PATH",
            std::env::join_paths(paths).expect("paths without ':'"),
        );
        command
    }

    /// The folder that holds example-robot-data's robots and the packages
    /// their `package://` mesh paths name (`--package-path` for
    /// `rodyn-model view`).
    pub fn package_share(&self) -> Result<PathBuf> {
        let purelib = setup::output(self.command().args([
            "-c",
            "import sysconfig; print(sysconfig.get_paths()['purelib'])",
        ]))?;
        Ok(Path::new(purelib.trim()).join("cmeel.prefix/share"))
    }

    /// The folder of example-robot-data's robots.
    pub fn robots(&self) -> Result<PathBuf> {
        Ok(self.package_share()?.join("example-robot-data/robots"))
    }
}

/// The test command's venv, made or updated when needed.
pub fn ensure() -> Result<Venv> {
    let root = shell::target_dir().join("python-venv");
    let venv = Venv { root };
    if !venv.python().exists() {
        let python = find_python()?;
        println!(
            "set-up: a Python venv in {} (Pinocchio's bindings are the reference)",
            venv.root.display()
        );
        shell::run(Command::new(&python).arg("-m").arg("venv").arg(&venv.root))?;
    }
    let stamp = venv.root.join("rodyn-requirements.txt");
    let wanted = REQUIREMENTS.join("\n");
    if std::fs::read_to_string(&stamp).ok().as_deref() != Some(wanted.as_str()) {
        println!(
            "set-up: pip install {} (into the venv)",
            REQUIREMENTS.join(" ")
        );
        shell::run(
            venv.command()
                .args([
                    "-m",
                    "pip",
                    "install",
                    "--quiet",
                    "--disable-pip-version-check",
                ])
                .args(REQUIREMENTS),
        )?;
        std::fs::write(&stamp, wanted).context("cannot record the venv's requirements")?;
    }
    Ok(venv)
}

/// A Python 3.9 or newer with the `venv` module (the wheel's floor).
fn find_python() -> Result<PathBuf> {
    for name in ["python3", "python"] {
        let ok = Command::new(name)
            .args([
                "-c",
                "import sys, venv, ensurepip; sys.exit(sys.version_info < (3, 9))",
            ])
            .status()
            .is_ok_and(|s| s.success());
        if ok {
            return Ok(PathBuf::from(name));
        }
    }
    bail!(
        "the tests need Python 3.9 or newer with venv and pip; on Debian or Ubuntu: \
         sudo apt-get install python3 python3-venv python3-pip"
    )
}
