//! Warnings about a model that loads but would not behave as its author
//! expects: a mass matrix that is singular at the neutral configuration
//! (`q = 0`: every joint at zero, floating bases at the identity), where
//! forward dynamics refuses to run, and frames that a planar model drops
//! because they leave its plane.

use crate::codegen::generated_frames;
use crate::description::ModelDescription;
use crate::diagnostic::{Diagnostic, Location};
use crate::runtime::{PaddedRuntimeModel, MAX_NV};
use rodyn::algorithm::crba::crba;
use rodyn::algorithm::dense::cholesky_in_place;
use rodyn::Data;

/// A pivot of the mass matrix's Cholesky factor below this many f64
/// epsilons of its own diagonal entry counts as zero (the tolerance of
/// rodyn's `Lᵀ D L` factorisation, so that the warning and the run-time
/// refusal agree).
const PIVOT_TOLERANCE_EPS: f64 = 64.0;

/// The warnings of this module for `model`.
#[must_use]
pub fn warnings(model: &ModelDescription) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    // A planar model runs as its 3-D equivalent here, whose out-of-plane
    // directions a flat model need not fill: only 3-D models are tested.
    if !model.planar {
        out.extend(singular_at_neutral(model));
    }
    if model.planar {
        out.extend(frames_off_the_plane(model));
    }
    out
}

/// A warning naming the joint at which the mass matrix at `q = 0` stops
/// being positive definite (a joint that moves nothing its ancestors do
/// not already move, such as two coaxial joints at one point with no
/// inertia between them), or `None`.
#[must_use]
pub fn singular_at_neutral(model: &ModelDescription) -> Option<Diagnostic> {
    let nv = model.nv();
    if nv == 0 || nv > MAX_NV {
        return None;
    }
    let runtime = PaddedRuntimeModel::new(model.clone()).ok()?;
    let mut data = Box::new(Data::new());
    let q = runtime.model.neutral_configuration();
    let m = crba(&runtime.model, &mut data, &q).ok()?;
    // The file's coordinates come first; the padding after them is
    // massless and left out.
    let mut a: Box<[[f64; MAX_NV]; MAX_NV]> = Box::new([[0.0; MAX_NV]; MAX_NV]);
    for r in 0..nv {
        for c in 0..=r {
            a[r][c] = m[r][c];
        }
    }
    let row = cholesky_in_place(&mut a, nv, PIVOT_TOLERANCE_EPS).err()?;
    let starts = model.idx_v();
    let body = starts.iter().rposition(|&s| s <= row)?;
    let b = &model.bodies[body];
    Some(Diagnostic::warning(
        b.location.clone(),
        format!(
            "the mass matrix is singular at the neutral configuration (q = 0) at joint `{}` (velocity coordinate {row}): it moves nothing that the joints above it do not already move, so forward dynamics will refuse this configuration; give the links below it mass or inertia, or check its axis",
            b.joint_name
        ),
    ))
}

/// One warning per frame that a planar model leaves out of its generated
/// frames because the frame leaves the x-y plane.
fn frames_off_the_plane(model: &ModelDescription) -> Vec<Diagnostic> {
    let kept: Vec<&str> = generated_frames(model)
        .iter()
        .map(|(f, _, _)| f.name.as_str())
        .collect();
    model
        .frames
        .iter()
        .filter(|f| f.body.is_some() && !kept.contains(&f.name.as_str()))
        .map(|f| {
            let location = f
                .body
                .and_then(|b| model.bodies.get(b))
                .map_or_else(|| Location::start_of("".as_ref()), |b| b.location.clone());
            Diagnostic::warning(
                location,
                format!(
                    "frame `{}` leaves the x-y plane of this planar model (out-of-plane offset or rotation) and is left out of the generated frames",
                    f.name
                ),
            )
        })
        .collect()
}
