//! `rodyn-model`: compile, inspect and draw model files.
//!
//! ```text
//! rodyn-model rust   <file> [--module NAME] [--floating-base] [--strict]   print the generated Rust
//! rodyn-model check  <file> [--floating-base] [--strict]                   check the file, print warnings
//!
//! Every command also takes `--round-quarter-turns` and `--silence KINDS`
//! (comma-separated kinds of warning, such as `limit,geometry`, or `all`).
//! rodyn-model tree   <file> [--floating-base] [--strict]                   bodies, joints, endpoints, drives
//! rodyn-model render <file> [--q a,b,...] [--view xy|xz|yz|iso] [-o out.svg]   stick figure
//! rodyn-model view   <file> [--q a,b,...] [--package-path DIR]... [--trajectory run.csv] [-o robot.html]   3-D viewer page
//! ```

use rodyn_model::description::JointType;
use rodyn_model::joint_limits::read_joint_limits;
use rodyn_model::names::module_name;
use rodyn_model::render::{render_svg, View};
use rodyn_model::runtime::RuntimeModel;
use rodyn_model::tree::render_tree;
use rodyn_model::view;
use rodyn_model::visual::read_visuals;
use rodyn_model::{build::generate_source, LoadOptions, WarningKinds};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

mod trajectory_csv;

const USAGE: &str = "usage:
  rodyn-model rust  <file> [--module <NAME>] [--floating-base] [--strict]   print the generated Rust module
  rodyn-model check <file> [--floating-base] [--strict]                     check a model file and print its warnings
  rodyn-model tree  <file> [--floating-base] [--strict]                     print bodies, joints, endpoints, drives, nq and nv
  rodyn-model render <file> [--floating-base] [--strict] [--q <a,b,...>] [--view <xy|xz|yz|iso>] [--width <PX>] [-o <out.svg>]
                                                               draw a stick figure at q (default: zeros; planar models view xy, others iso)
                                                               --width from 16 to 10000 px (default 480); each of q finite, at most 1e6 in size
  rodyn-model view  <file> [--floating-base] [--q <a,b,...>] [--package-path <DIR>]... [--trajectory <run.csv>] [-o <robot.html>]
                                                               write a 3-D viewer as one HTML file (meshes from the URDF; package://NAME/ found as DIR/NAME);
                                                               --trajectory replays a CSV of t (s) and the nq coordinates per line, under a header line
options for every command: --round-quarter-turns, --silence <KINDS> (comma-separated kinds of warning, or all: limit, dynamics, mimic, geometry, transmission, gazebo, calibration, unknown-element, unnamed-robot, fixed-root-inertia, massless-tensor, link-tensor, body-tensor)";

/// The picture's width (px) unless `--width` says otherwise, and its bounds.
const DEFAULT_WIDTH: f64 = 480.0;
const WIDTH_RANGE: (f64, f64) = (16.0, 10_000.0);

/// The largest size of a coordinate `--q` takes (rad or m): beyond it a
/// picture shows nothing a smaller value would not.
const MAX_COORDINATE: f64 = 1e6;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("{message}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &[String]) -> Result<(), String> {
    let (command, rest) = args.split_first().ok_or(USAGE)?;
    if matches!(command.as_str(), "-h" | "--help" | "help") {
        return emit(&format!("{USAGE}\n"));
    }
    let mut file: Option<PathBuf> = None;
    let mut module = None;
    let mut options = LoadOptions::default();
    let mut q: Vec<f64> = Vec::new();
    let mut view = None;
    let mut output = None;
    let mut width = DEFAULT_WIDTH;
    // Options that only some commands read, as given, with those commands:
    // refused elsewhere rather than silently ignored.
    let mut command_only: Vec<(&str, &[&str])> = Vec::new();
    let mut package_path: Vec<PathBuf> = Vec::new();
    let mut trajectory: Option<PathBuf> = None;
    let mut it = rest.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--module" => {
                let name = it.next().ok_or("--module needs a name")?;
                // The generator would rename it; say so instead.
                let usable = module_name(name);
                if &usable != name {
                    return Err(format!(
                        "--module: `{name}` is not a Rust module name; `{usable}` would be"
                    ));
                }
                module = Some(name.clone());
            }
            "--floating-base" => options.floating_base = true,
            "--strict" => options.strict = true,
            "--round-quarter-turns" => options.round_quarter_turns = true,
            "--silence" => {
                let list = it
                    .next()
                    .ok_or("--silence needs kinds of warning, such as limit,geometry")?;
                options.silence = options
                    .silence
                    .union(WarningKinds::parse(list).map_err(|e| format!("--silence: {e}"))?);
            }
            "--q" => {
                let list = it.next().ok_or("--q needs comma-separated numbers")?;
                q = list
                    .split(',')
                    .map(coordinate)
                    .collect::<Result<_, _>>()
                    .map_err(|e| format!("--q: {e}"))?;
                command_only.push(("--q", &["render", "view"]));
            }
            "--view" => {
                let v = it.next().ok_or("--view needs xy, xz, yz or iso")?;
                view = Some(
                    View::parse(v)
                        .ok_or(format!("--view: unknown view `{v}`; use xy, xz, yz or iso"))?,
                );
                command_only.push(("--view", &["render"]));
            }
            "--width" => {
                let w = it.next().ok_or("--width needs a number of pixels")?;
                width = pixels(w).map_err(|e| format!("--width: {e}"))?;
                command_only.push(("--width", &["render"]));
            }
            "--package-path" => {
                package_path.push(PathBuf::from(
                    it.next()
                        .ok_or("--package-path needs a folder that holds packages")?,
                ));
                command_only.push(("--package-path", &["view"]));
            }
            "--trajectory" => {
                trajectory = Some(PathBuf::from(
                    it.next()
                        .ok_or("--trajectory needs a CSV file of t and q per line")?,
                ));
                command_only.push(("--trajectory", &["view"]));
            }
            "-o" | "--output" => {
                output = Some(PathBuf::from(it.next().ok_or("-o needs a file name")?));
                command_only.push(("-o", &["render", "view"]));
            }
            other if other.starts_with('-') => {
                return Err(format!("unknown option {other}\n{USAGE}"))
            }
            other => {
                if let Some(first) = &file {
                    return Err(format!(
                        "two model files, {} and {other}: give one",
                        first.display()
                    ));
                }
                file = Some(PathBuf::from(other));
            }
        }
    }
    let file = file.ok_or(USAGE)?;
    if let Some((option, commands)) = command_only
        .iter()
        .find(|(_, commands)| !commands.contains(&command.as_str()))
    {
        return Err(format!(
            "{option} applies to `{}` only, not to `{command}`",
            commands.join("` and `")
        ));
    }
    if command != "rust" && module.is_some() {
        return Err(format!(
            "--module applies to `rust` only, not to `{command}`"
        ));
    }
    match command.as_str() {
        "rust" => {
            let stem = file
                .file_stem()
                .map_or("model".into(), |s| s.to_string_lossy().into_owned());
            let (source, model) =
                generate_source(&file, module.as_deref().unwrap_or(&stem), options)
                    .map_err(|d| d.to_string())?;
            for w in &model.warnings {
                eprintln!("{w}");
            }
            emit(&source)
        }
        "check" => {
            // The same checks as code generation (distinct names, a planar
            // model in its plane, values that fit f32), so that `check`
            // never passes a file that `rust` or a build script refuses.
            let stem = file
                .file_stem()
                .map_or("model".into(), |s| s.to_string_lossy().into_owned());
            let model = rodyn_model::load(&file, options).map_err(|d| d.to_string())?;
            rodyn_model::codegen::generate(&model, &stem, &file.display().to_string())
                .map_err(|d| d.to_string())?;
            for w in &model.warnings {
                eprintln!("{w}");
            }
            emit(&format!(
                "{}: ok, {} bodies, nq = {}, nv = {}\n",
                file.display(),
                model.bodies.len(),
                model.nq(),
                model.nv()
            ))
        }
        "tree" => {
            let model = rodyn_model::load(&file, options).map_err(|d| d.to_string())?;
            emit(&render_tree(&model))
        }
        "render" => {
            let model = rodyn_model::load(&file, options).map_err(|d| d.to_string())?;
            if !q.is_empty() && q.len() != model.nq() {
                return Err(format!(
                    "--q has {} numbers but the model has nq = {}",
                    q.len(),
                    model.nq()
                ));
            }
            let view = view.unwrap_or(if model.planar {
                View::Xy
            } else {
                View::Isometric
            });
            let runtime = RuntimeModel::new(model).map_err(|d| d.to_string())?;
            let svg = render_svg(&runtime, &q, view, width)
                .map_err(|e| format!("cannot pose the model: {e}"))?;
            match output {
                Some(path) => {
                    std::fs::write(&path, svg).map_err(|e| format!("-o {}: {e}", path.display()))?
                }
                None => emit(&svg)?,
            }
            Ok(())
        }
        "view" => {
            let model = rodyn_model::load(&file, options).map_err(|d| d.to_string())?;
            if !q.is_empty() && q.len() != model.nq() {
                return Err(format!(
                    "--q has {} numbers but the model has nq = {}",
                    q.len(),
                    model.nq()
                ));
            }
            let visuals = read_visuals(&model, &package_path).map_err(|d| d.to_string())?;
            for w in &visuals.warnings {
                eprintln!("{w}");
            }
            let limits = read_joint_limits(&model).map_err(|d| d.to_string())?;
            let runtime = RuntimeModel::new(model).map_err(|d| d.to_string())?;
            let mut scene = view::scene(&runtime, visuals, &q);
            for (body, limits) in scene.bodies.iter_mut().zip(limits) {
                body.limits = limits;
            }
            if let Some(csv) = &trajectory {
                let text = std::fs::read_to_string(csv)
                    .map_err(|e| format!("--trajectory {}: {e}", csv.display()))?;
                let (t, mut qs) = trajectory_csv::read(
                    &text,
                    &csv.display().to_string(),
                    runtime.description().nq(),
                )?;
                // The free flyers' quaternions, in the file's layout.
                let mut starts = Vec::new();
                let mut k = 0;
                for body in &runtime.description().bodies {
                    k += match body.joint {
                        JointType::FreeFlyer => {
                            starts.push(k + 3);
                            7
                        }
                        JointType::PlanarFloating => 3,
                        _ => 1,
                    };
                }
                trajectory_csv::normalise_quaternions(&mut qs, &starts);
                scene.trajectory = Some(
                    view::trajectory(&runtime, &t, &qs, Vec::new())
                        .map_err(|e| format!("--trajectory {}: {e}", csv.display()))?,
                );
            }
            let html = rodyn_viewer::write_html(&scene)
                .map_err(|e| format!("cannot write the page: {e}"))?;
            let path = output
                .unwrap_or_else(|| PathBuf::from(format!("{}.html", runtime.description().name)));
            std::fs::write(&path, html).map_err(|e| format!("{}: {e}", path.display()))?;
            emit(&format!("wrote {}\n", path.display()))
        }
        _ => Err(format!("unknown command `{command}`\n{USAGE}")),
    }
}

/// One coordinate of `--q`: a finite number of sensible size.
fn coordinate(text: &str) -> Result<f64, String> {
    let x: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number"))?;
    if !x.is_finite() {
        Err(format!("`{text}` is not a finite number"))
    } else if x.abs() > MAX_COORDINATE {
        Err(format!(
            "`{text}` is beyond the limit of {MAX_COORDINATE:e} in size"
        ))
    } else {
        Ok(x)
    }
}

/// The picture's width: a finite number of pixels within [`WIDTH_RANGE`].
fn pixels(text: &str) -> Result<f64, String> {
    let w: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number of pixels"))?;
    let (min, max) = WIDTH_RANGE;
    if (min..=max).contains(&w) {
        Ok(w)
    } else {
        Err(format!("`{text}` is outside {min} to {max} px"))
    }
}

/// Writes `text` to standard output. A reader that stopped early (`| head`)
/// is no error: what it wanted it has. (`rodyn_cli::emit` for the other
/// tools; this crate keeps its own, since `rodyn-cli` is only its test
/// dependency and the model compiler is every firmware's build dependency.)
fn emit(text: &str) -> Result<(), String> {
    match std::io::stdout().lock().write_all(text.as_bytes()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(format!("cannot write to standard output: {e}"))
        }
        _ => Ok(()),
    }
}
