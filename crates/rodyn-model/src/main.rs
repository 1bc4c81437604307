//! `rodyn-model`: compile, inspect and draw model files.
//!
//! ```text
//! rodyn-model rust   <file> [--module NAME] [--floating-base]   print the generated Rust
//! rodyn-model check  <file> [--floating-base]                   check the file, print warnings
//! ```

use rodyn_model::{build::generate_source, LoadOptions};
use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str = "usage:
  rodyn-model rust  <file> [--module NAME] [--floating-base]   print the generated Rust module
  rodyn-model check <file> [--floating-base]                   check a model file and print its warnings";

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
    let mut it = rest.iter();
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "--module" => module = Some(it.next().ok_or("--module needs a name")?.clone()),
            "--floating-base" => options.floating_base = true,
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
            let model = rodyn_model::load(&file, options).map_err(|d| d.to_string())?;
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
        _ => Err(USAGE.to_string()),
    }
}
