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
//! ```

use rodyn_model::render::{render_svg, View};
use rodyn_model::runtime::RuntimeModel;
use rodyn_model::tree::render_tree;
use rodyn_model::{build::generate_source, LoadOptions, WarningKinds};
use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str = "usage:
  rodyn-model rust  <file> [--module NAME] [--floating-base] [--strict]   print the generated Rust module
  rodyn-model check <file> [--floating-base] [--strict]                   check a model file and print its warnings
  rodyn-model tree  <file> [--floating-base] [--strict]                   print bodies, joints, endpoints, drives, nq and nv
  rodyn-model render <file> [--floating-base] [--strict] [--q a,b,...] [--view xy|xz|yz|iso] [--width PX] [-o out.svg]
                                                               draw a stick figure at q (default: zeros; planar models view xy, others iso)
options for every command: --round-quarter-turns, --silence KINDS (comma-separated kinds of warning, or all: limit, dynamics, mimic, geometry, transmission, gazebo, calibration, unknown-element, unnamed-robot, fixed-root-inertia, massless-tensor, link-tensor, body-tensor)";

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
    let mut file = None;
    let mut module = None;
    let mut options = LoadOptions::default();
    let mut q: Vec<f64> = Vec::new();
    let mut view = None;
    let mut output = None;
    let mut width = 480.0;
    let mut it = rest.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--module" => module = Some(it.next().ok_or("--module needs a name")?.clone()),
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
                    .map(|x| {
                        x.trim()
                            .parse::<f64>()
                            .map_err(|_| format!("--q: `{x}` is not a number"))
                    })
                    .collect::<Result<_, _>>()?;
            }
            "--view" => {
                let v = it.next().ok_or("--view needs xy, xz, yz or iso")?;
                view = Some(
                    View::parse(v)
                        .ok_or(format!("--view: unknown view `{v}`; use xy, xz, yz or iso"))?,
                );
            }
            "--width" => {
                width = it
                    .next()
                    .and_then(|w| w.parse().ok())
                    .ok_or("--width needs a number of pixels")?;
            }
            "-o" | "--output" => {
                output = Some(PathBuf::from(it.next().ok_or("-o needs a file name")?))
            }
            other if other.starts_with("--") => {
                return Err(format!("unknown option {other}\n{USAGE}"))
            }
            other => file = Some(PathBuf::from(other)),
        }
    }
    let file = file.ok_or(USAGE)?;
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
            print!("{source}");
            Ok(())
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
            println!(
                "{}: ok, {} bodies, nq = {}, nv = {}",
                file.display(),
                model.bodies.len(),
                model.nq(),
                model.nv()
            );
            Ok(())
        }
        "tree" => {
            let model = rodyn_model::load(&file, options).map_err(|d| d.to_string())?;
            print!("{}", render_tree(&model));
            Ok(())
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
                    std::fs::write(&path, svg).map_err(|e| format!("{}: {e}", path.display()))?
                }
                None => print!("{svg}"),
            }
            Ok(())
        }
        _ => Err(USAGE.to_string()),
    }
}
