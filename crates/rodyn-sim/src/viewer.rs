//! `rodyn-sim run --html`: the run as a 3-D viewer page, the scenario's
//! model read from its file in `models/` (the file `rodyn-scenarios`
//! compiles, so the recorded q has its layout) and every pose from rodyn's
//! forward kinematics.

use crate::run::foot_contacts;
use crate::scenario::{IntegratorKind, RunConfig, Scenario};
use crate::trajectory::Trajectory;
use rodyn_model::runtime::RuntimeModel;
use rodyn_model::{view, visual, LoadOptions};
use rodyn_viewer::ContactPoint;
use std::path::{Path, PathBuf};

/// The model file a scenario simulates.
fn model_file(scenario: Scenario) -> PathBuf {
    let file = match scenario {
        Scenario::ArmSwing => "panda.toml",
        Scenario::QuadrupedStand | Scenario::QuadrupedTrot => "aibo.toml",
        Scenario::MuscleRobot => "two_link_muscles.toml",
    };
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../models")
        .join(file)
}

/// Writes the page of `trajectory`, a run of `config`, to `path`. The
/// contacts are the compliant ground's, recomputed from the recorded
/// state; a rigid-contact run's impulses are not recorded, so its page
/// has none.
pub fn write_page(
    config: &RunConfig,
    trajectory: &Trajectory,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let scenario = config.scenario;
    let file = model_file(scenario);
    let description = rodyn_model::load(&file, LoadOptions::default())
        .map_err(|d| format!("the scenario's model: {d}"))?;
    let visuals = visual::read_visuals(&description, &[])?;
    let model = RuntimeModel::new(description)?;
    let contacts = if scenario.has_feet() && config.integrator != IntegratorKind::RigidContact {
        foot_contacts(trajectory)?
            .iter()
            .map(|feet| {
                feet.iter()
                    // A foot in the air has no contact to draw.
                    .filter(|c| c.force.x != 0.0 || c.force.y != 0.0 || c.force.z != 0.0)
                    .map(|c| ContactPoint {
                        position: [c.position.x, c.position.y, c.position.z],
                        force: [c.force.x, c.force.y, c.force.z],
                    })
                    .collect()
            })
            .collect()
    } else {
        Vec::new()
    };
    let mut scene = view::scene(&model, visuals, &[]);
    scene.name = format!("{} ({})", scene.name, scenario.name());
    scene.trajectory = Some(view::trajectory(
        &model,
        &trajectory.t,
        &trajectory.q,
        contacts,
    )?);
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::write(path, rodyn_viewer::write_html(&scene)?)?;
    Ok(())
}
