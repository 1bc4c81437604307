//! `rodyn-sim run --model FILE`: a user's URDF or TOML file simulated with
//! the run-time model (`rodyn_model::runtime::RuntimeModel`), no build
//! step: motion under gravity from the neutral configuration at rest, no
//! joint torque, the file's drives (springs, dampers, muscles at zero
//! activation, motors at zero current) acting when it has any, and with
//! `--ground` a compliant floor under contact points (`ground.rs`), a
//! floating base dropped onto it from `--drop-height`.
//! Writes `<model>.csv` (t, q, v), `<model>.svg` (the first coordinates
//! against time) and, with `--html`, the viewer page.

use crate::ground::{Ground, GroundOptions};
use crate::plot::{plot, Figure, Mark, Scale, Series};
use crate::progress::Progress;
use crate::scenario::{IntegratorKind, Method};
use crate::trajectory::Trajectory;
use clap::ValueEnum;
use rodyn_model::description::JointType;
use rodyn_model::runtime::{RuntimeError, RuntimeModel, Workspace};
use rodyn_model::{view, visual, LoadOptions};
use std::path::Path;
use std::time::Instant;

/// Most coordinates drawn on the plot (the CSV has them all).
const PLOTTED: usize = 8;

/// What `run --model` simulates.
pub struct FileRun<'a> {
    /// The model file (URDF or rodyn TOML).
    pub model: &'a Path,
    /// A URDF's root on a free-flyer.
    pub floating_base: bool,
    /// Simulated time (s).
    pub duration: f64,
    /// Step (s).
    pub dt: f64,
    /// Forward dynamics.
    pub method: Method,
    /// Integrator.
    pub integrator: IntegratorKind,
    /// Interval between samples (s).
    pub sample_interval: f64,
    /// The ground (`--ground`), when asked for.
    pub ground: Option<GroundOptions>,
    /// Height (m) of the lowest contact point at the start, for a floating
    /// base on the ground (`--drop-height`; `None`: the default).
    pub drop_height: Option<f64>,
}

/// Height of the lowest contact point above the ground at the start of a
/// floating model's run on the ground, when `--drop-height` is not given (m).
pub const DEFAULT_DROP_HEIGHT: f64 = 0.05;

/// The integrators a file run offers; the others name themselves.
///
/// # Errors
/// The implicit Euler (its Jacobian is the built-in scenes') and rigid
/// contact (the quadruped's feet only).
pub fn check_integrator(integrator: IntegratorKind) -> Result<(), String> {
    match integrator {
        IntegratorKind::ExplicitEuler | IntegratorKind::SemiImplicitEuler | IntegratorKind::Rk4 => Ok(()),
        other => Err(format!(
            "--integrator {} is not available with --model (explicit-euler, semi-implicit-euler and rk4 are)",
            other
                .to_possible_value()
                .map_or_else(|| format!("{other:?}"), |v| v.get_name().to_string())
        )),
    }
}

/// The model, its workspace and the method: `q̈ = FD(q, v, τ)` with `τ`
/// the ground's and the drives' generalized forces.
struct Dynamics<'m> {
    model: &'m RuntimeModel,
    ws: Workspace,
    method: Method,
    ground: Option<Ground>,
    /// The drives' inputs (all zero), when the file has drives.
    drive_inputs: Option<Vec<f64>>,
    tau: Vec<f64>,
    drive_tau: Vec<f64>,
}

impl Dynamics<'_> {
    fn acceleration(&mut self, q: &[f64], v: &[f64], out: &mut [f64]) -> Result<(), RuntimeError> {
        self.tau.fill(0.0);
        if let Some(ground) = &mut self.ground {
            ground.add_torques(self.model, &mut self.ws, q, v, &mut self.tau)?;
        }
        if let Some(w) = &self.drive_inputs {
            self.model
                .drive_generalized_forces(&mut self.ws, q, v, w, &mut self.drive_tau)?;
            for (t, d) in self.tau.iter_mut().zip(&self.drive_tau) {
                *t += d;
            }
        }
        match self.method {
            Method::Aba => self.model.aba(&mut self.ws, q, v, &self.tau, out),
            Method::Crba => self
                .model
                .forward_dynamics_crba(&mut self.ws, q, v, &self.tau, out),
        }
    }

    /// One step of `integrator` from `(q, v)`.
    fn step(
        &mut self,
        integrator: IntegratorKind,
        dt: f64,
        q: &mut Vec<f64>,
        v: &mut [f64],
    ) -> Result<(), RuntimeError> {
        let nv = v.len();
        let mut a = vec![0.0; nv];
        let mut next = vec![0.0; q.len()];
        match integrator {
            IntegratorKind::ExplicitEuler => {
                self.acceleration(q, v, &mut a)?;
                self.model.integrate(&mut self.ws, q, v, dt, &mut next)?;
                v.iter_mut().zip(&a).for_each(|(vk, ak)| *vk += dt * ak);
            }
            IntegratorKind::Rk4 => {
                // Classical RK4 on (q, v), each stage's configuration moved
                // along the joints' manifolds from q (a free-flyer's
                // rates summed in its frame at q).
                let mut stage_q = q.to_vec();
                let mut stage_v = v.to_vec();
                let (mut sum_v, mut sum_a) = (vec![0.0; nv], vec![0.0; nv]);
                for (k, (weight, reach)) in [(1.0, 0.5), (2.0, 0.5), (2.0, 1.0), (1.0, 0.0)]
                    .into_iter()
                    .enumerate()
                {
                    self.acceleration(&stage_q, &stage_v, &mut a)?;
                    for j in 0..nv {
                        sum_v[j] += weight * stage_v[j];
                        sum_a[j] += weight * a[j];
                    }
                    if k < 3 {
                        let rate = stage_v.clone();
                        self.model
                            .integrate(&mut self.ws, q, &rate, reach * dt, &mut stage_q)?;
                        for j in 0..nv {
                            stage_v[j] = v[j] + reach * dt * a[j];
                        }
                    }
                }
                let mean_v: Vec<f64> = sum_v.iter().map(|x| x / 6.0).collect();
                self.model
                    .integrate(&mut self.ws, q, &mean_v, dt, &mut next)?;
                v.iter_mut()
                    .zip(&sum_a)
                    .for_each(|(vk, ak)| *vk += dt * ak / 6.0);
            }
            // Semi-implicit Euler (and the refused ones never get here).
            _ => {
                self.acceleration(q, v, &mut a)?;
                v.iter_mut().zip(&a).for_each(|(vk, ak)| *vk += dt * ak);
                self.model.integrate(&mut self.ws, q, v, dt, &mut next)?;
            }
        }
        *q = next;
        Ok(())
    }
}

/// The CSV's names of the configuration coordinates: each joint's name,
/// a free-flyer's seven with their suffixes.
fn q_names(model: &RuntimeModel) -> Vec<String> {
    let mut names = Vec::new();
    for (joint, body) in model.joint_names().iter().zip(&model.description().bodies) {
        if body.joint.nq() == 1 {
            names.push(joint.clone());
        } else {
            for s in ["x", "y", "z", "qx", "qy", "qz", "qw"] {
                names.push(format!("{joint}_{s}"));
            }
        }
    }
    names
}

/// Runs `run`, writes the CSV and the plot into `out` and the page to
/// `html`, and prints a summary.
///
/// # Errors
/// The model file's diagnostic, an unwritable output, a run that fails
/// (named by its time).
pub fn run_file(
    run: &FileRun<'_>,
    out: &Path,
    html: Option<&Path>,
) -> Result<(), Box<dyn std::error::Error>> {
    let options = LoadOptions::new().with_floating_base(run.floating_base);
    let description = rodyn_model::load(run.model, options).map_err(|d| d.to_string())?;
    if description.planar {
        return Err(format!(
            "--model {}: a planar model runs in its own built-in scenes; --model simulates 3-D models",
            run.model.display()
        )
        .into());
    }
    let model = RuntimeModel::new(description.clone()).map_err(|d| d.to_string())?;
    let (nq, nv) = (model.nq(), model.nv());
    let steps = (run.duration / run.dt).round() as u64;
    let every = ((run.sample_interval / run.dt).round() as u64).max(1);
    let name = description.name.clone();
    let ground = run
        .ground
        .as_ref()
        .map(|options| Ground::new(&model, options))
        .transpose()?;
    let floating = description
        .bodies
        .first()
        .is_some_and(|b| b.joint == JointType::FreeFlyer);
    if run.drop_height.is_some() && !(floating && ground.is_some()) {
        return Err(format!(
            "--drop-height: it places a floating base above the ground; {} {}",
            run.model.display(),
            if floating {
                "runs without --ground"
            } else {
                "has a fixed base (a URDF takes --floating-base)"
            }
        )
        .into());
    }
    let mut dynamics = Dynamics {
        model: &model,
        ws: model.workspace(),
        method: run.method,
        ground,
        drive_inputs: (!model.drive_names().is_empty()).then(|| vec![0.0; model.nu()]),
        tau: vec![0.0; nv],
        drive_tau: vec![0.0; nv],
    };
    let (mut q, mut v) = (model.neutral(), vec![0.0; nv]);
    if let (Some(ground), true) = (&dynamics.ground, floating) {
        let lowest = ground.lowest(&model, &mut dynamics.ws, &q)?;
        q[2] += run.drop_height.unwrap_or(DEFAULT_DROP_HEIGHT) - lowest;
    }
    let progress = Progress::new("model file", steps);
    let mut trajectory = Trajectory::new(nq, nv);
    trajectory.steps = steps as usize;
    let record = |t: f64, q: &[f64], v: &[f64], trajectory: &mut Trajectory| {
        trajectory.t.push(t);
        trajectory.q.push(q.to_vec());
        trajectory.v.push(v.to_vec());
    };
    record(0.0, &q, &v, &mut trajectory);
    let start = Instant::now();
    for k in 1..=steps {
        if let Err(e) = dynamics.step(run.integrator, run.dt, &mut q, &mut v) {
            trajectory.failure = Some(format!("t = {} s: {e}", (k - 1) as f64 * run.dt));
            break;
        }
        if k % every == 0 {
            record(k as f64 * run.dt, &q, &v, &mut trajectory);
        }
        if k % 1024 == 0 {
            progress.at(k);
        }
    }
    trajectory.wall_time = start.elapsed();
    progress.finish();

    std::fs::create_dir_all(out)?;
    let csv = out.join(format!("{name}.csv"));
    trajectory.write_csv(&csv, &q_names(&model))?;
    let names = q_names(&model);
    let series: Vec<Series> = (0..nq.min(PLOTTED))
        .map(|k| {
            let points = trajectory
                .t
                .iter()
                .zip(&trajectory.q)
                .map(|(t, q)| (*t, q[k]))
                .collect();
            Series::new(names[k].clone(), points, Mark::Line, k)
        })
        .collect();
    let title = match &dynamics.ground {
        Some(_) => format!("{name} on the ground"),
        None => format!("{name} moving freely under gravity"),
    };
    let figure = Figure {
        title: &title,
        x_label: "time (s)",
        y_label: "configuration (rad, m)",
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
    };
    let svg = out.join(format!("{name}.svg"));
    plot(&svg, &figure, &series)?;
    if let Some(page) = html {
        let visuals = visual::read_visuals(&description, &[])?;
        let mut scene = view::scene(&model, visuals, &[]);
        let what = if dynamics.ground.is_some() {
            "on the ground"
        } else {
            "free motion"
        };
        scene.name = format!("{} ({what})", scene.name);
        scene.trajectory = Some(view::trajectory(
            &model,
            &trajectory.t,
            &trajectory.q,
            Vec::new(),
        )?);
        std::fs::write(page, rodyn_viewer::write_html(&scene)?)?;
        println!("wrote {}", page.display());
    }
    println!(
        "{name}: nq = {nq}, nv = {nv}, {} samples, {:.3} s of host time; wrote {} and {}",
        trajectory.t.len(),
        trajectory.wall_time.as_secs_f64(),
        csv.display(),
        svg.display()
    );
    if let Some(ground) = &dynamics.ground {
        println!(
            "ground at z = 0 under {} point(s): {}",
            ground.len(),
            ground.frames()
        );
    }
    if let Some(w) = &dynamics.drive_inputs {
        println!(
            "drives acting: {} (their {} input(s) at zero)",
            model.drive_names().join(", "),
            w.len()
        );
    }
    match trajectory.failure {
        Some(f) => {
            Err(format!("the simulation failed at {f} (the files hold the run up to there)").into())
        }
        None => Ok(()),
    }
}
