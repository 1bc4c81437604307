//! `rodyn-sim run`: one scenario to CSV, SVG plots and a GIF.

use crate::animate::{planar_stick_figure_gif, stick_figure_gif};
use crate::models::arm7;
use crate::plot::{plot, plot_panels, Curve, Figure, Mark, Panel, Scale, Series};
use crate::progress::Progress;
use crate::scenario::{run, RunConfig, Scenario};
use crate::trajectory::Trajectory;
use rodyn::sim::contact::ContactReport;
use rodyn::space::VectorOps;
use rodyn::spatial::Force;
use rodyn::Data;
use rodyn_scenarios::quadruped::{self, QuadrupedLoads, LEGS, LEG_NAMES};
use rodyn_scenarios::{muscle_robot, two_link_muscles};
use std::path::Path;

/// Runs `config`, writes `<scenario>.csv`, `<scenario>.svg` and
/// `<scenario>.gif` into `out` (and the viewer page to `html`, when
/// asked), and prints a summary.
pub fn run_command(
    config: &RunConfig,
    out: &Path,
    html: Option<&Path>,
) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all(out)?;
    let steps = (config.duration / config.dt).round() as u64;
    let progress = Progress::new(config.scenario.name(), steps);
    let trajectory = run(config, Some(&progress));
    progress.finish();
    let name = config.scenario.name();
    let csv = out.join(format!("{name}.csv"));
    let plot_path = out.join(format!("{name}.svg"));
    let gif = out.join(format!("{name}.gif"));
    // The quadruped's foot forces (N), beside its torso position (m).
    let forces_path = out.join(format!("{name}-forces.svg"));
    let frame = 0.04;
    match config.scenario {
        Scenario::ArmSwing => {
            let names: Vec<String> = (1..=7).map(|k| format!("joint{k}")).collect();
            trajectory.write_csv(&csv, &names)?;
            let series = (0..7)
                .map(|k| {
                    Series::new(
                        format!("joint {}", k + 1),
                        column(&trajectory, k),
                        Mark::Line,
                        k,
                    )
                })
                .collect::<Vec<_>>();
            plot(
                &plot_path,
                &figure("7-DoF arm swinging under gravity", "joint angle (rad)"),
                &series,
            )?;
            stick_figure_gif(&gif, &arm7::<f64>(), &[], &trajectory, frame, false)?;
        }
        Scenario::QuadrupedStand | Scenario::QuadrupedTrot => {
            let mut names: Vec<String> = ["x", "y", "z", "qx", "qy", "qz", "qw"]
                .iter()
                .map(|s| s.to_string())
                .collect();
            for leg in LEG_NAMES {
                for joint in ["hip_pitch", "hip_roll", "knee"] {
                    names.push(format!("{leg}_{joint}"));
                }
            }
            trajectory.write_csv(&csv, &names)?;
            let forces = foot_forces(&trajectory)?;
            // Lengths and forces on plots of their own: one unit per axis.
            let series = vec![
                Series::new("torso x", column(&trajectory, 0), Mark::Line, 0),
                Series::new(
                    "torso z",
                    trajectory
                        .t
                        .iter()
                        .zip(&trajectory.q)
                        .map(|(t, q)| (*t, trunk_height(q)))
                        .collect(),
                    Mark::ThinLine,
                    1,
                ),
            ];
            plot(
                &plot_path,
                &figure(
                    &format!("quadruped: {name}, torso position"),
                    "position (m)",
                ),
                &series,
            )?;
            // A trot moves diagonal legs together: one panel per diagonal
            // pair, so that each foot's force can be followed (four spiky
            // curves on one axis hide one another).
            let diagonals = [(0, 3), (1, 2)];
            let panels = diagonals
                .iter()
                .map(|&(a, b)| Panel {
                    title: format!("{} and {} feet", LEG_NAMES[a], LEG_NAMES[b]),
                    series: [(a, Mark::Line), (b, Mark::ThinLine)]
                        .into_iter()
                        .map(|(leg, mark)| {
                            Series::new(
                                format!("{} foot", LEG_NAMES[leg]),
                                forces[leg].clone(),
                                mark,
                                2 + leg,
                            )
                        })
                        .collect(),
                })
                .collect::<Vec<_>>();
            plot_panels(
                &forces_path,
                &figure(
                    &format!("quadruped: {name}, ground's normal force on each foot"),
                    "normal force (N)",
                ),
                &panels,
                3,
            )?;
            let model = quadruped::model::<f64>()?;
            stick_figure_gif(
                &gif,
                &model,
                &quadruped::feet::<f64>(),
                &trajectory,
                frame,
                config.scenario == Scenario::QuadrupedTrot,
            )?;
        }
        Scenario::MuscleRobot => {
            let names = ["shoulder".to_string(), "elbow".to_string()];
            trajectory.write_csv(&csv, &names)?;
            let mut series = vec![
                Series::new(
                    "shoulder angle (rad)",
                    column(&trajectory, 0),
                    Mark::Line,
                    0,
                ),
                Series::new("elbow angle (rad)", column(&trajectory, 1), Mark::Line, 1),
            ];
            for k in 0..muscle_robot::NU {
                let activation = trajectory
                    .t
                    .iter()
                    .zip(&trajectory.internal)
                    .map(|(t, a)| (*t, a[k]))
                    .collect();
                series.push(Series::new(
                    format!("activation m{}", k + 1),
                    activation,
                    Mark::ThinLine,
                    2 + k,
                ));
            }
            plot(
                &plot_path,
                &figure(
                    "two-link robot, four muscles, example excitations",
                    "rad, activation",
                ),
                &series,
            )?;
            let hand = [two_link_muscles::ENDPOINTS_F64[two_link_muscles::endpoint::HAND]];
            let muscles = muscle_robot::MUSCLES_F64;
            let paths: Vec<&[_]> = muscles.iter().map(|m| &m.path.points[..]).collect();
            planar_stick_figure_gif(
                &gif,
                &muscle_robot::MODEL_F64,
                &hand,
                &paths,
                &trajectory,
                frame,
            )?;
        }
    }
    let last_t = trajectory.t.last().copied().unwrap_or(0.0);
    rodyn_cli::outln!(
        "{name}: {} {} {} dt = {} s, simulated {last_t:.3} s in {:.3} s of host time ({:.2e} s per simulated s)",
        config.method_name(),
        config.scalar.name(),
        config.integrator.name(),
        config.dt,
        trajectory.wall_time.as_secs_f64(),
        trajectory.cost_per_simulated_second()
    );
    if let Some(q) = trajectory.q.last() {
        if matches!(
            config.scenario,
            Scenario::QuadrupedStand | Scenario::QuadrupedTrot
        ) {
            let q: [f64; quadruped::NQ] = q.as_slice().try_into()?;
            let p = quadruped::trunk_position(&q);
            rodyn_cli::outln!(
                "final torso position x = {:.4} m, y = {:.4} m, z = {:.4} m",
                p.x,
                p.y,
                p.z
            );
        }
    }
    if let (Some(q), Some(a)) = (trajectory.q.last(), trajectory.internal.last()) {
        rodyn_cli::outln!(
            "final joint angles {:.4} {:.4} rad, activations {:.3} {:.3} {:.3} {:.3}",
            q[0],
            q[1],
            a[0],
            a[1],
            a[2],
            a[3]
        );
    }
    rodyn_cli::outln!(
        "wrote {}, {}, {}",
        csv.display(),
        plot_path.display(),
        gif.display()
    );
    if forces_path.exists() {
        rodyn_cli::outln!("wrote {}", forces_path.display());
    }
    if let Some(page) = html {
        crate::viewer::write_page(config, &trajectory, page)?;
        rodyn_cli::outln!("wrote {}", page.display());
    }
    match &trajectory.failure {
        // The files hold the run up to the failure, for a look at it.
        Some(f) => {
            Err(format!("the simulation failed at {f} (the files hold the run up to there)").into())
        }
        None => Ok(()),
    }
}

fn figure<'a>(title: &'a str, y: &'a str) -> Figure<'a> {
    Figure {
        title,
        x_label: "time (s)",
        y_label: y,
        x_scale: Scale::Linear,
        y_scale: Scale::Linear,
    }
}

fn column(t: &Trajectory, k: usize) -> Vec<(f64, f64)> {
    t.t.iter().zip(&t.q).map(|(t, q)| (*t, q[k])).collect()
}

/// The trunk's world height (m) in a recorded configuration (the model
/// file places the floating joint above the world origin).
fn trunk_height(q: &[f64]) -> f64 {
    q.try_into().map_or(f64::NAN, |q: [f64; quadruped::NQ]| {
        quadruped::trunk_position(&q).z
    })
}

/// Normal force of each foot at each sample, recomputed in f64 from the
/// recorded state with the scenario's ground.
pub fn foot_forces(trajectory: &Trajectory) -> Result<Vec<Curve>, Box<dyn std::error::Error>> {
    let mut out = vec![Vec::new(); LEGS];
    for (t, reports) in trajectory.t.iter().zip(foot_contacts(trajectory)?) {
        for (leg, report) in reports.iter().enumerate() {
            out[leg].push((*t, report.force.z));
        }
    }
    Ok(out)
}

/// Each foot's contact (point and ground force, world frame) at each
/// sample, recomputed in f64 from the recorded state with the scenario's
/// ground.
pub fn foot_contacts(
    trajectory: &Trajectory,
) -> Result<Vec<[ContactReport<f64>; LEGS]>, Box<dyn std::error::Error>> {
    let model = quadruped::model::<f64>()?;
    let mut loads = QuadrupedLoads::<f64>::standing();
    let mut data = Data::new();
    let mut out = Vec::with_capacity(trajectory.t.len());
    for (q, v) in trajectory.q.iter().zip(&trajectory.v) {
        // An f32 run's quaternion, widened to f64, is unit only to f32
        // precision: project it before the f64 checks see it.
        let mut q: [f64; quadruped::NQ] = q.as_slice().try_into()?;
        model.normalize(&mut q)?;
        let v: [f64; quadruped::NV] = v.as_slice().try_into()?;
        let mut f_ext = [Force::ZERO; quadruped::NB];
        loads.ground.add_forces(
            &model,
            &mut data,
            &q,
            &v,
            &loads.feet,
            &mut f_ext,
            Some(&mut loads.reports),
        )?;
        out.push(loads.reports);
    }
    Ok(out)
}
