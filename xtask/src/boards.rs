//! The board images of `boards/`: built for their three cores and checked.
//!
//! Each board is a crate in `boards/` whose `.cargo/config.toml` names its
//! target and its probe-rs runner; nothing here can flash one. `cargo xtask
//! test` (and `cargo xtask boards`) builds every image, then fails when an
//! image's flash grows by more than [`SIZE_TOLERANCE`] over
//! `boards/expected/sizes.txt`, when an image does not fit its chip's flash
//! or RAM (the `FLASH` and `RAM` lengths of the board's `memory.x`), or when
//! rodyn has a panic call site in it (`crate::panic_sites`). `cargo xtask
//! boards --bless` records the sizes of an intended change. The build lints
//! the boards' crates with clippy as it compiles them, warnings as errors
//! ([`shell::lint_while_building`]); `cargo xtask lint` adds rustfmt
//! ([`lint`]).

use crate::{firmware, panic_sites, setup, shell};
use anyhow::{bail, Context, Result};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// One board image.
pub struct Board {
    /// The crate's folder in `boards/` and its binary's name.
    pub name: &'static str,
    /// Chip, core and scalar, for the log.
    pub about: &'static str,
    /// Rust target (the one its `.cargo/config.toml` sets).
    pub target: &'static str,
    /// Its target directory below `target/boards`, when it needs its own:
    /// the Cortex-M7's `target-cpu` would rebuild the nRF52840's crates in
    /// a shared one.
    pub own_target_dir: Option<&'static str>,
}

/// Every board, one per core.
pub const BOARDS: [Board; 3] = [
    Board {
        name: "nrf52840-dk",
        about: "nRF52840-DK: nRF52840, Cortex-M4F at 64 MHz, f32",
        target: "thumbv7em-none-eabihf",
        own_target_dir: None,
    },
    Board {
        name: "nucleo-h743zi",
        about: "Nucleo-H743ZI: STM32H743ZI, Cortex-M7 at 400 MHz, f64 on its double-precision FPU",
        target: "thumbv7em-none-eabihf",
        own_target_dir: Some("cortex-m7"),
    },
    Board {
        name: "pico2",
        about: "Raspberry Pi Pico 2: RP2350, Cortex-M33 at 150 MHz, f32",
        target: "thumbv8m.main-none-eabihf",
        own_target_dir: None,
    },
];

/// Growth of an image's flash over its recorded size accepted without
/// failing (fraction).
const SIZE_TOLERANCE: f64 = 0.01;

/// The boards' workspace.
fn workspace() -> PathBuf {
    shell::root().join("boards")
}

fn sizes_path() -> PathBuf {
    workspace().join("expected/sizes.txt")
}

impl Board {
    fn dir(&self) -> PathBuf {
        workspace().join(self.name)
    }

    /// Passed to cargo, so that a `CARGO_TARGET_DIR` in the environment
    /// cannot put two boards of one target into one folder.
    fn target_dir(&self) -> PathBuf {
        let dir = shell::target_dir().join("boards");
        match self.own_target_dir {
            Some(own) => dir.join(own),
            None => dir,
        }
    }

    /// The image after [`Self::build`].
    pub fn elf(&self) -> PathBuf {
        self.target_dir()
            .join(self.target)
            .join("release")
            .join(self.name)
    }

    /// Builds the image in release mode, with the source paths that reach
    /// flash remapped as the firmware's are (`firmware::cargo_command_in`),
    /// and clippy's lints on the boards' crates.
    fn build(&self) -> Result<()> {
        let mut command = firmware::cargo_command_in(&workspace(), self.target, &[]);
        command
            .current_dir(self.dir())
            .args(["build", "--release", "--target-dir"])
            .arg(self.target_dir());
        shell::lint_while_building(&mut command)?;
        shell::run(&mut command)
    }
}

/// An image's sections (`llvm-size -B`), bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Size {
    text: u64,
    data: u64,
    bss: u64,
}

impl Size {
    /// What goes to flash: code, read-only data and the initial values of
    /// the initialised statics.
    fn flash(self) -> u64 {
        self.text + self.data
    }
    /// Statics in RAM, before the stack.
    fn ram(self) -> u64 {
        self.data + self.bss
    }

    fn measure(elf: &Path) -> Result<Self> {
        let out = setup::output(Command::new(setup::llvm_size()?).arg("-B").arg(elf))?;
        let numbers: Vec<u64> = out
            .lines()
            .nth(1)
            .with_context(|| format!("llvm-size printed no sizes for {}", elf.display()))?
            .split_whitespace()
            .take(3)
            .map(str::parse)
            .collect::<Result<_, _>>()
            .context("llvm-size output")?;
        Ok(Self {
            text: numbers[0],
            data: numbers[1],
            bss: numbers[2],
        })
    }

    fn line(self, name: &str) -> String {
        format!(
            "{name} text={} data={} bss={}",
            self.text, self.data, self.bss
        )
    }
}

/// The recorded sizes: board → size.
fn recorded() -> Result<BTreeMap<String, Size>> {
    let path = sizes_path();
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let mut sizes = BTreeMap::new();
    for (number, line) in text.lines().enumerate() {
        if line.starts_with('#') || line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split_whitespace().collect();
        let value = |key: &str| -> Result<u64> {
            fields
                .iter()
                .find_map(|f| f.strip_prefix(key)?.strip_prefix('='))
                .with_context(|| {
                    format!("{}:{}: no {key}= in `{line}`", path.display(), number + 1)
                })?
                .parse()
                .with_context(|| {
                    format!("{}:{}: {key} is not a number", path.display(), number + 1)
                })
        };
        let size = Size {
            text: value("text")?,
            data: value("data")?,
            bss: value("bss")?,
        };
        sizes.insert(fields[0].to_string(), size);
    }
    Ok(sizes)
}

/// The `LENGTH` of the `FLASH` and `RAM` regions of a board's `memory.x`
/// (`1024K`, `2M` or bytes).
fn memory_lengths(board: &Board) -> Result<(u64, u64)> {
    let path = board.dir().join("memory.x");
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let length = |region: &str| -> Result<u64> {
        let line = text
            .lines()
            .find(|l| l.split_whitespace().next() == Some(region) && l.contains("LENGTH"))
            .with_context(|| format!("{}: no {region} region with a LENGTH", path.display()))?;
        let value = line
            .split("LENGTH")
            .nth(1)
            .and_then(|rest| rest.trim_start().strip_prefix('='))
            .map(str::trim)
            .with_context(|| format!("{}: no LENGTH in `{}`", path.display(), line.trim()))?;
        let (digits, scale) = match value.chars().last() {
            Some('K') => (&value[..value.len() - 1], 1 << 10),
            Some('M') => (&value[..value.len() - 1], 1 << 20),
            _ => (value, 1),
        };
        let n: u64 = digits.parse().with_context(|| {
            format!(
                "{}: LENGTH `{value}` of {region} is not a size",
                path.display()
            )
        })?;
        Ok(n * scale)
    };
    Ok((length("FLASH")?, length("RAM")?))
}

/// `cargo xtask boards [--bless]`.
pub fn run(args: &[String]) -> Result<()> {
    match args {
        [] => check(),
        [flag] if flag == "--bless" => bless(),
        _ => bail!("usage: cargo xtask boards [--bless]"),
    }
}

/// Builds every board image, timing each build.
fn build_all() -> Result<()> {
    setup::ensure_family_targets()?;
    for board in &BOARDS {
        let started = Instant::now();
        board.build()?;
        println!(
            "board {}: built in {:.0} s",
            board.name,
            started.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

/// Builds every image and checks its size, its fit and its panic sites.
pub fn check() -> Result<()> {
    let started = Instant::now();
    build_all()?;
    let recorded = recorded()?;
    let mut failures = Vec::new();
    for board in &BOARDS {
        let size = Size::measure(&board.elf())?;
        let (flash, ram) = memory_lengths(board)?;
        let mut sites: BTreeMap<&str, usize> =
            panic_sites::SOURCES.iter().map(|s| (*s, 0)).collect();
        for site in panic_sites::sites_in(&board.elf())? {
            *sites.entry(site.source).or_default() += 1;
        }
        let rodyn_sites = sites.get(panic_sites::NO_SITES).copied().unwrap_or(0);
        let growth = match recorded.get(board.name) {
            Some(before) => {
                let growth = size.flash() as f64 / before.flash() as f64 - 1.0;
                if growth > SIZE_TOLERANCE {
                    failures.push(format!(
                        "{}: flash grew from {} to {} B (more than {} %; `cargo xtask boards --bless` records an intended change)",
                        board.name,
                        before.flash(),
                        size.flash(),
                        100.0 * SIZE_TOLERANCE
                    ));
                }
                format!("{:+.1} % against {}", 100.0 * growth, before.flash())
            }
            None => {
                failures.push(format!(
                    "{}: no size recorded in {} (`cargo xtask boards --bless`)",
                    board.name,
                    sizes_path().display()
                ));
                "not recorded".to_string()
            }
        };
        if size.flash() > flash {
            failures.push(format!(
                "{}: {} B of flash, its memory.x has {flash}",
                board.name,
                size.flash()
            ));
        }
        if size.ram() > ram {
            failures.push(format!(
                "{}: {} B of statics, its memory.x has {ram} B of RAM",
                board.name,
                size.ram()
            ));
        }
        if rodyn_sites > 0 {
            failures.push(format!(
                "{}: {rodyn_sites} panic call sites of rodyn's",
                board.name
            ));
        }
        let sites: Vec<String> = sites.iter().map(|(s, n)| format!("{s} {n}")).collect();
        println!(
            "board {} ({}): flash {} of {flash} B ({growth}), static RAM {} of {ram} B; panic call sites: {}",
            board.name,
            board.about,
            size.flash(),
            size.ram(),
            sites.join(", ")
        );
    }
    if !failures.is_empty() {
        bail!("board images: {}", failures.join("; "));
    }
    println!(
        "xtask boards: {} images built and checked in {:.0} s",
        BOARDS.len(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// rustfmt over the boards' workspace, and clippy on each board through
/// its build (nothing to compile when `test` built them already), warnings
/// as errors (a step of `cargo xtask lint`).
pub fn lint() -> Result<()> {
    shell::cargo_in(workspace(), &["fmt", "--all", "--check"])?;
    build_all()
}

/// Rewrites `boards/expected/sizes.txt` from fresh builds.
fn bless() -> Result<()> {
    build_all()?;
    let mut text = String::from(
        "# Board image sizes (bytes, llvm-size -B) recorded by `cargo xtask boards --bless`.\n\
         # `cargo xtask test` fails when an image's flash (text + data) grows by more than 1 %.\n",
    );
    for board in &BOARDS {
        text.push_str(&Size::measure(&board.elf())?.line(board.name));
        text.push('\n');
    }
    std::fs::write(sizes_path(), &text)
        .with_context(|| format!("cannot write {}", sizes_path().display()))?;
    print!("{text}");
    Ok(())
}
