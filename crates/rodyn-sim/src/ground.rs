//! The ground under a model file's run (`run --model FILE --ground`): a
//! compliant floor at `z = 0` pushing on contact points, the law of the
//! built-in scenes' feet (`rodyn::sim::contact::GroundContact`: a linear
//! spring-damper along the normal, Coulomb friction regularised by a slip
//! velocity).
//!
//! The contact points are frame origins: the ones named with `--contact`,
//! else the file's own `[[contact]]`s (with their stiffness, damping and
//! friction), else every frame of the model. A point's force `f` reaches
//! the joints as `Jᵀ f`, `J` the linear rows of its frame's Jacobian in
//! world axes at the point, so the run-time model's public calls are all
//! a run needs.

use rodyn::sim::contact::{GroundContact, NormalLaw};
use rodyn::spatial::Vec3;
use rodyn_model::description::{Contact, ModelDescription};
use rodyn_model::runtime::{Reference, RuntimeError, RuntimeModel, Workspace};

/// The static sink of a contact point the default stiffness allows (m):
/// the model's weight shared evenly between its points sinks each by this.
const DEFAULT_SINK: f64 = 1e-3;
/// Friction coefficient when neither `--friction` nor the file gives one
/// (the value the repository's quadruped files use).
const DEFAULT_FRICTION: f64 = 0.8;
/// Gravity (m/s²) that sizes the default stiffness of a model without any.
const STANDARD_GRAVITY: f64 = 9.80665;

/// What the command line asks of the ground.
#[derive(Clone, Debug, Default)]
pub struct GroundOptions {
    /// `--contact` frames (empty: the file's contacts, else every frame).
    pub contacts: Vec<String>,
    /// `--friction`, overriding the file's.
    pub friction: Option<f64>,
    /// `--restitution`, setting every point's damping.
    pub restitution: Option<f64>,
}

/// One contact point: its frame and its ground law.
struct Point {
    frame: String,
    law: GroundContact<f64>,
}

/// The ground of a run, with the scratch of its Jacobians.
pub struct Ground {
    points: Vec<Point>,
    jacobian: Vec<f64>,
}

/// The damping ratio `ζ` of a linear spring-damper whose bounce keeps the
/// fraction `e` of the impact velocity: `e = exp(−ζ π / √(1 − ζ²))`
/// solved for `ζ` (`e = 0`: critical damping).
fn damping_ratio(restitution: f64) -> f64 {
    if restitution <= 0.0 {
        return 1.0;
    }
    let log = restitution.ln();
    -log / (std::f64::consts::PI * std::f64::consts::PI + log * log).sqrt()
}

impl Ground {
    /// The ground of `model` under `options`.
    ///
    /// # Errors
    /// A `--contact` that names no frame or is given twice, a file contact
    /// whose endpoint is not a frame, a model without frames.
    pub fn new(model: &RuntimeModel, options: &GroundOptions) -> Result<Self, String> {
        let description = model.description();
        let frames = model.frame_names();
        let file_contact = |frame: &str| -> Option<&Contact> {
            description
                .contacts
                .iter()
                .find(|c| description.endpoints[c.endpoint].name == frame)
        };
        let names: Vec<String> = if !options.contacts.is_empty() {
            for (k, name) in options.contacts.iter().enumerate() {
                if !frames.contains(name) {
                    return Err(format!(
                        "--contact {name}: the model has no such frame (its frames: {})",
                        frames.join(", ")
                    ));
                }
                if options.contacts[..k].contains(name) {
                    return Err(format!("--contact {name} is given twice"));
                }
            }
            options.contacts.clone()
        } else if !description.contacts.is_empty() {
            description
                .contacts
                .iter()
                .map(|c| {
                    let endpoint = &description.endpoints[c.endpoint].name;
                    if frames.contains(endpoint) {
                        Ok(endpoint.clone())
                    } else {
                        Err(format!(
                            "--ground: the file's contact '{}' is at endpoint '{endpoint}', which is not a frame; name the contact frames with --contact",
                            c.name
                        ))
                    }
                })
                .collect::<Result<_, _>>()?
        } else if frames.is_empty() {
            return Err("--ground: the model has no frame to stand on".to_owned());
        } else {
            frames.clone()
        };
        let count = names.len();
        let default_law = default_law(description, count);
        let points = names
            .into_iter()
            .map(|frame| {
                let mut law = file_contact(&frame).map_or(default_law, |c| GroundContact {
                    normal: NormalLaw::LinearSpringDamper {
                        stiffness: c.stiffness,
                        damping: c.damping,
                    },
                    friction: c.friction,
                    slip_scale: c.slip_velocity,
                });
                if let Some(mu) = options.friction {
                    law.friction = mu;
                }
                if let (Some(e), NormalLaw::LinearSpringDamper { stiffness, damping }) =
                    (options.restitution, &mut law.normal)
                {
                    *damping = critical_damping(description, *stiffness, count) * damping_ratio(e);
                }
                Point { frame, law }
            })
            .collect();
        Ok(Self {
            points,
            jacobian: vec![0.0; 6 * model.nv()],
        })
    }

    /// Contact points.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// The contact frames, comma-separated.
    pub fn frames(&self) -> String {
        self.points
            .iter()
            .map(|p| p.frame.as_str())
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The lowest contact point's height (m) at `q`.
    ///
    /// # Errors
    /// As [`RuntimeModel::frame_placement`].
    pub fn lowest(
        &self,
        model: &RuntimeModel,
        ws: &mut Workspace,
        q: &[f64],
    ) -> Result<f64, RuntimeError> {
        let mut placement = [0.0; 16];
        let mut lowest = f64::INFINITY;
        for p in &self.points {
            model.frame_placement(ws, q, &p.frame, &mut placement)?;
            lowest = lowest.min(placement[11]);
        }
        Ok(lowest)
    }

    /// Adds the ground's generalized forces `Σ Jᵀ f` at `(q, v)` to `tau`.
    ///
    /// # Errors
    /// As [`RuntimeModel::frame_jacobian`]; a ground force that cannot be
    /// evaluated, named by its frame.
    pub fn add_torques(
        &mut self,
        model: &RuntimeModel,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        tau: &mut [f64],
    ) -> Result<(), RuntimeError> {
        let nv = v.len();
        let mut placement = [0.0; 16];
        for p in &self.points {
            model.frame_placement(ws, q, &p.frame, &mut placement)?;
            if placement[11] > 0.0 {
                continue;
            }
            let position = Vec3::new(placement[3], placement[7], placement[11]);
            model.frame_jacobian(
                ws,
                q,
                &p.frame,
                Reference::LocalWorldAligned,
                &mut self.jacobian,
            )?;
            let rows = self.jacobian.chunks_exact(nv);
            let mut velocity = [0.0; 3];
            for (vel, row) in velocity.iter_mut().zip(rows) {
                *vel = row.iter().zip(v).map(|(j, x)| j * x).sum();
            }
            let force = p
                .law
                .force_at(&position, &Vec3::new(velocity[0], velocity[1], velocity[2]))
                .map_err(|e| {
                    RuntimeError::invalid_input(format!("ground at frame '{}': {e}", p.frame))
                })?;
            for (row, f) in self
                .jacobian
                .chunks_exact(nv)
                .zip([force.x, force.y, force.z])
            {
                for (t, j) in tau.iter_mut().zip(row) {
                    *t += j * f;
                }
            }
        }
        Ok(())
    }
}

/// The damping (N s/m) that damps critically a point carrying an even
/// share of the model's mass over `points` points on `stiffness`.
fn critical_damping(description: &ModelDescription, stiffness: f64, points: usize) -> f64 {
    let share = description.total_mass() / points.max(1) as f64;
    2.0 * (stiffness * share).sqrt()
}

/// The law of a point the file says nothing about: stiff enough that an
/// even share of the weight on `points` points sinks [`DEFAULT_SINK`],
/// critically damped, [`DEFAULT_FRICTION`], the file format's default
/// slip velocity.
fn default_law(description: &ModelDescription, points: usize) -> GroundContact<f64> {
    let g = description.gravity;
    let g = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    let g = if g > 0.0 { g } else { STANDARD_GRAVITY };
    let share = description.total_mass() / points.max(1) as f64;
    let stiffness = share * g / DEFAULT_SINK;
    GroundContact {
        normal: NormalLaw::LinearSpringDamper {
            stiffness,
            damping: critical_damping(description, stiffness, points),
        },
        friction: DEFAULT_FRICTION,
        slip_scale: Contact::DEFAULT_SLIP_VELOCITY,
    }
}

#[cfg(test)]
mod tests {
    use super::damping_ratio;

    #[test]
    fn the_damping_ratio_gives_back_the_restitution() {
        for e in [0.05, 0.3, 0.5, 0.9] {
            let zeta: f64 = damping_ratio(e);
            let bounce = (-zeta * std::f64::consts::PI / (1.0 - zeta * zeta).sqrt()).exp();
            assert!((bounce - e).abs() < 1e-12, "{e}: {bounce}");
        }
        assert_eq!(damping_ratio(0.0), 1.0);
        assert!(damping_ratio(1.0).abs() < 1e-15);
    }
}
