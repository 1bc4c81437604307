//! The viewer's pages in a real browser: headless Chromium (software WebGL)
//! opens pages written by `rodyn-model view` and `rodyn-sim run --html`
//! and checks that
//!
//! - every page of the shipped models, and a run's, draws a frame without
//!   an error (each page, opened in a frame of a harness page, posts its
//!   status: `ready`, or `error: …` after an exception or a
//!   `console.error`; `--dump-dom` reads the harness's list);
//! - the robot is drawn: a screenshot of the Panda differs from one with
//!   the robot layer hidden over at least [`MIN_ROBOT_PIXELS`] of the 3-D
//!   view, and from the committed reference image over at most
//!   [`MAX_REFERENCE_PIXELS`];
//! - example-robot-data's robots with meshes ([`MESH_ROBOTS`]: the Panda's
//!   COLLADA, Solo12's STL, Talos's STL), from the test command's Python
//!   venv, load without an error and are drawn, as above;
//! - scrubbing moves the trot, and the firmware's arm controller and
//!   quadruped replayed from their pose logs (`cargo xtask run EXAMPLE
//!   --html`): screenshots at two times differ over at least
//!   [`MIN_MOTION_PIXELS`].
//!
//! A reference image that is missing is written (commit it); delete it to
//! take a new one after a deliberate change of the page.

use crate::{firmware, python_env, replay, setup, shell};
use anyhow::{bail, ensure, Context, Result};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// Screenshot size, pixels.
const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;
/// Pixels left of this column are the side panel (its text depends on the
/// fonts installed); the comparisons look at the 3-D view only.
const VIEW_LEFT: u32 = 290;
/// Two pixels differ when a channel differs by more than this (of 255):
/// above the shading noise of antialiased edges, below any real change.
const CHANNEL_TOLERANCE: u8 = 48;
/// Least share of the 3-D view the Panda's pixels must cover.
const MIN_ROBOT_PIXELS: f64 = 0.02;
/// Largest share of the 3-D view that may differ from the reference.
const MAX_REFERENCE_PIXELS: f64 = 0.01;
/// Least share of the 3-D view that must change between two times of the trot.
const MIN_MOTION_PIXELS: f64 = 0.005;
/// The firmware examples replayed from their pose logs, with two times
/// (s) of the run at which the robot must stand differently: the arm
/// early and late in its reference motion, the quadruped standing and
/// trotting.
const FIRMWARE_REPLAYS: [(&str, &str, &str); 2] =
    [("arm_control", "0.2", "1.2"), ("quadruped", "1", "4.5")];

/// example-robot-data's robots with meshes: page name, URDF under the
/// package share folder, whether the base floats, and the URL fragment of
/// the screenshots (the Panda's elbow bent).
const MESH_ROBOTS: [(&str, &str, bool, &str); 3] = [
    (
        "erd-panda",
        "example-robot-data/robots/panda_description/urdf/panda.urdf",
        false,
        "q=0.3,-0.4,0,-2.0,0,1.6,0.8,0.02,0.02",
    ),
    (
        "erd-solo12",
        "example-robot-data/robots/solo_description/robots/solo12.urdf",
        true,
        "",
    ),
    (
        "erd-talos",
        "example-robot-data/robots/talos_data/robots/talos_reduced.urdf",
        true,
        "",
    ),
];

/// The Panda's pose for the screenshots (rad): elbow bent, wrist turned.
const PANDA_Q: &str = "0.3,-0.4,0,-2.0,0,1.6,0.8";

/// Runs the checks (the viewer step of `cargo xtask test`).
pub fn check() -> Result<()> {
    let started = Instant::now();
    let chromium = ensure_chromium()?;
    shell::cargo(&["build", "-p", "rodyn-model", "-p", "rodyn-sim", "--bins"])?;
    let bin = shell::target_dir().join("debug");
    let root = shell::root();
    let work = shell::target_dir().join("viewer-check");
    // A fresh folder: no page of an earlier run can pass for this one.
    let _ = std::fs::remove_dir_all(&work);
    std::fs::create_dir_all(&work)?;

    // Every shipped model file's page, and a run's, draws without an error.
    let models = root.join("models");
    let mut pages = Vec::new();
    for file in model_files(&models)? {
        // `urdf/panda.urdf` becomes `urdf-panda.html`, beside `panda.html`.
        let relative = file.strip_prefix(&models).unwrap_or(&file);
        let name = relative
            .with_extension("html")
            .to_string_lossy()
            .replace('/', "-");
        let mut view = Command::new(bin.join("rodyn-model"));
        view.arg("view").arg(&file).arg("-o").arg(work.join(&name));
        view.args(["--silence", "all"]);
        run_quietly(&mut view)?;
        pages.push(name);
    }
    // example-robot-data's robots with their meshes.
    let share = python_env::ensure()?.package_share()?;
    for (name, urdf, floating, fragment) in MESH_ROBOTS {
        let mut view = Command::new(bin.join("rodyn-model"));
        view.arg("view")
            .arg(share.join(urdf))
            .arg("--package-path")
            .arg(&share);
        if floating {
            view.arg("--floating-base");
        }
        view.args(["--silence", "all", "-o"])
            .arg(work.join(format!("{name}.html")));
        run_quietly(&mut view)?;
        pages.push(format!("{name}.html#{fragment}"));
    }
    let trot = work.join("trot.html");
    let mut sim = Command::new(bin.join("rodyn-sim"));
    sim.args(["run", "quadruped-trot", "--duration", "1", "-o"])
        .arg(work.join("trot"))
        .arg("--html")
        .arg(&trot);
    run_quietly(&mut sim)?;
    pages.push("trot.html#t=0.5".into());
    // The firmware examples' runs, from their pose logs in QEMU.
    setup::ensure_target()?;
    setup::ensure_qemu()?;
    for (name, _, _) in FIRMWARE_REPLAYS {
        let example = firmware::example(name)?;
        let page = work.join(format!("{name}.html"));
        replay::write_page(example, &page, &bin.join("rodyn-model"), |_| {})?;
        pages.push(format!("{name}.html#t=1"));
    }
    let statuses = page_statuses(&chromium, &work, &pages)?;
    let broken: Vec<String> = statuses
        .iter()
        .filter(|(_, s)| s.as_str() != "ready")
        .map(|(p, s)| format!("{p}: {s}"))
        .collect();
    ensure!(
        broken.is_empty() && statuses.len() == pages.len(),
        "viewer pages in {} failed:\n{}",
        work.display(),
        broken.join("\n")
    );
    println!(
        "viewer: {} pages drew without an error ({:.0} s so far)",
        pages.len(),
        started.elapsed().as_secs_f64()
    );

    // The robot is drawn, as in the reference image.
    let panda = work.join("panda.html"); // models/panda.toml's
    let shots = [
        (work.join("panda.png"), url(&panda, &format!("q={PANDA_Q}"))),
        (
            work.join("panda-hidden.png"),
            url(&panda, &format!("q={PANDA_Q}&hide=robot")),
        ),
    ];
    let images = parallel(&shots, |(png, url)| screenshot(&chromium, url, png))?;
    let robot = differing_share(&images[0], &images[1]);
    ensure!(
        robot >= MIN_ROBOT_PIXELS,
        "the Panda covers {:.2} % of the 3-D view (at least {:.0} % expected): is it drawn?",
        100.0 * robot,
        100.0 * MIN_ROBOT_PIXELS
    );
    let reference = root.join("crates/rodyn-viewer/tests/reference/panda.png");
    if reference.exists() {
        let want = read_png(&reference)?;
        let off = differing_share(&images[0], &want);
        ensure!(
            off <= MAX_REFERENCE_PIXELS,
            "the Panda's screenshot {} differs from {} over {:.2} % of the 3-D view (at most {:.0} %)",
            shots[0].0.display(),
            reference.display(),
            100.0 * off,
            100.0 * MAX_REFERENCE_PIXELS
        );
        println!(
            "viewer: the Panda covers {:.1} % of the view; {:.2} % differs from the reference",
            100.0 * robot,
            100.0 * off
        );
    } else {
        std::fs::create_dir_all(reference.parent().unwrap_or(&root))?;
        std::fs::copy(&shots[0].0, &reference)?;
        println!(
            "viewer: wrote the reference image {} (commit it)",
            reference.display()
        );
    }

    // example-robot-data's robots are drawn: their meshes cover the view.
    for (name, _, _, fragment) in MESH_ROBOTS {
        let page = work.join(format!("{name}.html"));
        let hide = if fragment.is_empty() {
            "hide=robot".to_string()
        } else {
            format!("{fragment}&hide=robot")
        };
        let shots = [
            (work.join(format!("{name}.png")), url(&page, fragment)),
            (work.join(format!("{name}-hidden.png")), url(&page, &hide)),
        ];
        let images = parallel(&shots, |(png, url)| screenshot(&chromium, url, png))?;
        let robot = differing_share(&images[0], &images[1]);
        ensure!(
            robot >= MIN_ROBOT_PIXELS,
            "{name}: the robot covers {:.2} % of the 3-D view in {} (at least {:.0} % expected): are its meshes drawn?",
            100.0 * robot,
            shots[0].0.display(),
            100.0 * MIN_ROBOT_PIXELS
        );
        println!(
            "viewer: {name} (example-robot-data, meshes) covers {:.1} % of the view",
            100.0 * robot
        );
    }

    // Scrubbing a trajectory moves the robot: the firmware's replays.
    for (name, early, late) in FIRMWARE_REPLAYS {
        let page = work.join(format!("{name}.html"));
        let times = [
            (
                work.join(format!("{name}-{early}.png")),
                url(&page, &format!("t={early}")),
            ),
            (
                work.join(format!("{name}-{late}.png")),
                url(&page, &format!("t={late}")),
            ),
        ];
        let images = parallel(&times, |(png, url)| screenshot(&chromium, url, png))?;
        let moved = differing_share(&images[0], &images[1]);
        ensure!(
            moved >= MIN_MOTION_PIXELS,
            "{name}'s replay at {early} s and {late} s differs over {:.2} % of the 3-D view only (at least {:.1} %)",
            100.0 * moved,
            100.0 * MIN_MOTION_PIXELS
        );
        println!(
            "viewer: {name}'s replay (firmware pose log) at {early} s and {late} s differs over {:.1} % of the view",
            100.0 * moved
        );
    }
    // And the simulated trot.
    let times = [
        (work.join("trot-0.1.png"), url(&trot, "t=0.1")),
        (work.join("trot-0.9.png"), url(&trot, "t=0.9")),
    ];
    let images = parallel(&times, |(png, url)| screenshot(&chromium, url, png))?;
    let moved = differing_share(&images[0], &images[1]);
    ensure!(
        moved >= MIN_MOTION_PIXELS,
        "the trot at 0.1 s and 0.9 s differs over {:.2} % of the 3-D view only (at least {:.1} %)",
        100.0 * moved,
        100.0 * MIN_MOTION_PIXELS
    );
    println!(
        "viewer: the trot's frames at 0.1 s and 0.9 s differ over {:.1} % of the view; checks took {:.0} s",
        100.0 * moved,
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// `models/*.toml` and `models/urdf/*.urdf`, sorted.
fn model_files(models: &Path) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for dir in [models.to_path_buf(), models.join("urdf")] {
        for entry in std::fs::read_dir(&dir).with_context(|| dir.display().to_string())? {
            let path = entry?.path();
            if path.extension().is_some_and(|e| e == "toml" || e == "urdf") {
                files.push(path);
            }
        }
    }
    files.sort();
    Ok(files)
}

fn url(page: &Path, fragment: &str) -> String {
    let mut url = format!("file://{}", page.display());
    if !fragment.is_empty() {
        url.push('#');
        url.push_str(fragment);
    }
    url
}

/// Runs `command`, printing its output only when it fails.
fn run_quietly(command: &mut Command) -> Result<()> {
    let out = command
        .output()
        .with_context(|| format!("cannot start {}", shell::describe(command)))?;
    if !out.status.success() {
        bail!(
            "`{}` failed:\n{}{}",
            shell::describe(command),
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
    Ok(())
}

/// `f` of each item on two threads (Chromium spends most of its time
/// starting), results in order.
fn parallel<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> Result<R> + Sync) -> Result<Vec<R>> {
    let half = items.len().div_ceil(2);
    let (first, second) = items.split_at(half);
    let (a, b) = std::thread::scope(|s| {
        let other = s.spawn(|| second.iter().map(&f).collect::<Result<Vec<_>>>());
        let mine = first.iter().map(&f).collect::<Result<Vec<_>>>();
        (mine, other.join())
    });
    let mut out = a?;
    out.extend(b.map_err(|_| anyhow::anyhow!("a Chromium thread panicked"))??);
    Ok(out)
}

/// Headless Chromium with a fresh profile, software WebGL, no network
/// services, at the screenshot size; `--virtual-time-budget` lets the page
/// load and draw before Chromium reads it.
fn chromium_command(chromium: &Path, profile: &Path, budget_ms: u32) -> Command {
    let mut command = Command::new(chromium);
    command
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--force-device-scale-factor=1",
            "--enable-unsafe-swiftshader",
            "--use-angle=swiftshader",
        ])
        .arg(format!("--virtual-time-budget={budget_ms}"))
        .arg(format!("--window-size={WIDTH},{HEIGHT}"))
        .arg(format!("--user-data-dir={}", profile.display()));
    command
}

/// A fresh profile folder for one Chromium run, removed on drop.
struct Profile(PathBuf);

impl Profile {
    fn new() -> Result<Self> {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let dir = std::env::temp_dir().join(format!(
            "rodyn-viewer-chromium-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir)?;
        Ok(Self(dir))
    }
}

impl Drop for Profile {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Each page's status (`ready` or `error: …`) from one Chromium run: a
/// harness page in `work` opens them one after the other in a frame, and
/// each page posts its status to its parent once it has drawn or failed.
fn page_statuses(chromium: &Path, work: &Path, pages: &[String]) -> Result<Vec<(String, String)>> {
    let list = pages
        .iter()
        .map(|p| format!("'{}'", p.replace('\\', "\\\\").replace('\'', "\\'")))
        .collect::<Vec<_>>()
        .join(", ");
    let harness = work.join("harness.html");
    std::fs::write(&harness, HARNESS.replace("PAGES", &list))?;
    let profile = Profile::new()?;
    // Virtual time: the harness's waits cost nothing while pages are idle.
    let mut command = chromium_command(chromium, &profile.0, 600_000);
    command.arg("--dump-dom");
    command.arg(url(&harness, ""));
    let out = command
        .output()
        .with_context(|| format!("cannot start {}", shell::describe(&command)))?;
    let dom = String::from_utf8_lossy(&out.stdout);
    let Some(start) = dom.find("<pre id=\"results\">") else {
        bail!(
            "Chromium returned no results for {}:\n{}",
            harness.display(),
            String::from_utf8_lossy(&out.stderr)
        );
    };
    let text = &dom[start + 18..];
    let text = &text[..text.find("</pre>").unwrap_or(text.len())];
    Ok(text
        .lines()
        .filter_map(|line| line.split_once('\t'))
        .map(|(page, status)| (unescape(page), unescape(status)))
        .collect())
}

/// Text as `--dump-dom` escapes it, back.
fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&amp;", "&")
}

/// Opens each page of `PAGES` in a frame and lists `page<TAB>status`; a
/// page that says nothing within 20 s (of virtual time) did not start.
const HARNESS: &str = r#"<!DOCTYPE html>
<html><body><iframe id="page" width="640" height="480"></iframe><pre id="results"></pre>
<script>
const pages = [PAGES];
const lines = [];
let k = 0;
function next() {
  if (k === pages.length) { document.getElementById('results').textContent = lines.join('\n'); return; }
  const page = pages[k++];
  const timer = setTimeout(() => { lines.push(page + '\tthe page did not report'); next(); }, 20000);
  window.onmessage = (e) => { clearTimeout(timer); lines.push(page + '\t' + e.data); next(); };
  document.getElementById('page').src = page;
}
next();
</script></body></html>
"#;

/// An RGBA image.
struct Image {
    width: u32,
    height: u32,
    rgba: Vec<u8>,
}

fn screenshot(chromium: &Path, url: &str, png: &Path) -> Result<Image> {
    let profile = Profile::new()?;
    let mut command = chromium_command(chromium, &profile.0, 3000);
    command
        .arg(format!("--screenshot={}", png.display()))
        .arg(url);
    run_quietly(&mut command)?;
    read_png(png)
}

fn read_png(path: &Path) -> Result<Image> {
    let file = std::fs::File::open(path).with_context(|| path.display().to_string())?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info()?;
    let mut buffer = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buffer)?;
    let channels = info.color_type.samples();
    let rgba = buffer[..info.buffer_size()]
        .chunks(channels)
        .flat_map(|p| match channels {
            1 | 2 => [p[0], p[0], p[0], 255],
            3 => [p[0], p[1], p[2], 255],
            _ => [p[0], p[1], p[2], p[3]],
        })
        .collect();
    Ok(Image {
        width: info.width,
        height: info.height,
        rgba,
    })
}

/// The share of the 3-D view's pixels (right of [`VIEW_LEFT`]) where `a`
/// and `b` differ by more than [`CHANNEL_TOLERANCE`] in a colour channel;
/// 1 when the sizes differ.
fn differing_share(a: &Image, b: &Image) -> f64 {
    if a.width != b.width || a.height != b.height || a.width <= VIEW_LEFT {
        return 1.0;
    }
    let mut differing = 0usize;
    let mut total = 0usize;
    for y in 0..a.height {
        for x in VIEW_LEFT..a.width {
            let k = 4 * (y * a.width + x) as usize;
            total += 1;
            let far = (0..3).any(|c| a.rgba[k + c].abs_diff(b.rgba[k + c]) > CHANNEL_TOLERANCE);
            differing += usize::from(far);
        }
    }
    differing as f64 / total as f64
}

/// Chromium's path; installs Debian's `chromium` through apt-get as root
/// when it is missing, otherwise stops with the command to run.
fn ensure_chromium() -> Result<PathBuf> {
    let found = |p: &Path| {
        Command::new(p)
            .arg("--version")
            .output()
            .is_ok_and(|o| o.status.success())
    };
    let chromium = PathBuf::from("/usr/bin/chromium");
    if found(&chromium) {
        return Ok(chromium);
    }
    let install = "apt-get install -y --no-remove --no-install-recommends chromium";
    let is_root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0");
    if !is_root {
        bail!("the viewer's checks need Chromium; install it with:\n    sudo apt-get update && sudo {install}");
    }
    let apt = |args: &[&str]| {
        shell::run(
            Command::new("apt-get")
                .args(args)
                .env("DEBIAN_FRONTEND", "noninteractive"),
        )
    };
    // A fresh machine's package lists may be empty: update once on failure.
    let args: Vec<&str> = install.split(' ').skip(1).collect();
    if apt(&args).is_err() {
        apt(&["update"])?;
        apt(&args)?;
    }
    ensure!(
        found(&chromium),
        "{install} ran, but {} does not start",
        chromium.display()
    );
    Ok(chromium)
}
