//! rodyn's half of the example-robot-data sweep
//! (`tools/pinocchio/sweep_example_robot_data.py` runs it): loads each URDF
//! with the model compiler at run time, and evaluates RNEA, the mass matrix
//! (CRBA) and forward dynamics (`M⁻¹ (τ − h)`, the mass matrix's Cholesky
//! factor) at the states the script gives.
//!
//! ```text
//! cargo run --release -p rodyn-host-tests --example model_sweep -- IN.json OUT.json
//! ```
//!
//! `IN.json`: `[{"urdf": path, "floating_base": bool, "states": [{"q", "v", "tau"}]}]`
//! with `q` in rodyn's layout (one angle per continuous joint). `OUT.json`:
//! per robot `{"urdf", "loaded", "error"?, "warnings", "nq", "nv",
//! "states": [{"rnea", "mass_matrix", "forward_dynamics"}]}`.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::rnea::rnea;
use rodyn::Data;
use rodyn_cli::writable_file;
use rodyn_model::runtime::{PaddedRuntimeModel, MAX_BODIES, MAX_NV};
use rodyn_model::{load, LoadOptions};
use serde_json::{json, Value};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [input, output] = args.as_slice() else {
        return Err("usage: model_sweep IN.json OUT.json".into());
    };
    let text = std::fs::read_to_string(input).map_err(|e| format!("{input}: {e}"))?;
    let robots: Vec<Value> = serde_json::from_str(&text).map_err(|e| format!("{input}: {e}"))?;
    if robots.is_empty() {
        return Err(format!("{input}: no robots in the list").into());
    }
    // The output is checked before the sweep, not after it.
    writable_file(std::path::Path::new(output))?;
    let mut results = Vec::new();
    for (n, robot) in robots.iter().enumerate() {
        let urdf = robot["urdf"]
            .as_str()
            .ok_or_else(|| format!("{input}: robot {} has no \"urdf\" path", n + 1))?;
        eprintln!("[{}/{}] {urdf}", n + 1, robots.len());
        let options =
            LoadOptions::new().with_floating_base(robot["floating_base"].as_bool().unwrap_or(true));
        let description = match load(std::path::Path::new(urdf), options) {
            Ok(d) => d,
            Err(e) => {
                results.push(json!({"urdf": urdf, "loaded": false, "error": e.to_string()}));
                continue;
            }
        };
        let warnings = description.warnings.len();
        let (nq, nv) = (description.nq(), description.nv());
        let runtime = match PaddedRuntimeModel::new(description) {
            Ok(r) => r,
            Err(e) => {
                results.push(json!({"urdf": urdf, "loaded": false, "error": e.to_string()}));
                continue;
            }
        };
        let mut data: Box<Data<f64, MAX_BODIES, MAX_NV>> = Box::default();
        let mut states = Vec::new();
        for state in robot["states"].as_array().ok_or("states")? {
            let values = |k: &str| -> Vec<f64> {
                state[k]
                    .as_array()
                    .map_or_else(Vec::new, |a| a.iter().filter_map(Value::as_f64).collect())
            };
            let q = runtime.configuration(&values("q"));
            let mut v = [0.0; MAX_NV];
            let mut tau = [0.0; MAX_NV];
            v[..nv].copy_from_slice(&values("v"));
            tau[..nv].copy_from_slice(&values("tau"));
            let result = (|| -> Result<Value, rodyn::Error> {
                let torques = *rnea(&runtime.model, &mut data, &q, &v, &[0.0; MAX_NV], None)?;
                let rnea_a = {
                    let a: Vec<f64> = values("a");
                    let mut acc = [0.0; MAX_NV];
                    acc[..a.len().min(nv)].copy_from_slice(&a[..a.len().min(nv)]);
                    *rnea(&runtime.model, &mut data, &q, &v, &acc, None)?
                };
                let m = crba(&runtime.model, &mut data, &q)?;
                let block = nalgebra::DMatrix::from_fn(nv, nv, |r, c| m[r][c]);
                let rhs = nalgebra::DVector::from_fn(nv, |k, _| tau[k] - torques[k]);
                let ddq = block
                    .clone()
                    .cholesky()
                    .map(|c| c.solve(&rhs).iter().copied().collect::<Vec<f64>>());
                Ok(json!({
                    "rnea": rnea_a[..nv].to_vec(),
                    "mass_matrix": (0..nv).map(|r| m[r][..nv].to_vec()).collect::<Vec<_>>(),
                    "forward_dynamics": ddq,
                }))
            })();
            states.push(result.unwrap_or_else(|e| json!({"error": e.to_string()})));
        }
        results.push(json!({"urdf": urdf, "loaded": true, "warnings": warnings, "nq": nq, "nv": nv, "states": states}));
    }
    std::fs::write(output, serde_json::to_string(&results)?)
        .map_err(|e| format!("{output}: {e}"))?;
    Ok(())
}
