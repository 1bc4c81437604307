//! Physical plausibility of the numbers in a model file, checked where they
//! are written so the error can point at them.

use crate::codegen::mass_fits_f32;
use crate::description::ModelDescription;
use crate::diagnostic::{Diagnostic, Location, Result};
use crate::geometry::{symmetric_eigenvalues, Mat3};

/// Relative tolerance of the inertia checks: rounding in a file written with
/// six significant digits must not fail a physical body.
const RELATIVE_TOLERANCE: f64 = 1e-6;

/// Checks a link's mass (kg): finite and positive.
///
/// # Errors
/// A diagnostic at `location` naming `what`.
pub fn check_mass(mass: f64, what: &str, location: &Location) -> Result<()> {
    if mass.is_finite() && mass > 0.0 && !mass_fits_f32(mass) {
        Err(Diagnostic::error(
            location.clone(),
            format!("{what} has mass {mass:e}, which the model's f32 version cannot hold (nonzero masses from 1.2e-38 to 3.4e38 kg)"),
        ))
    } else if mass.is_finite() && mass > 0.0 {
        Ok(())
    } else {
        Err(Diagnostic::error(
            location.clone(),
            format!("{what} has mass {mass}; a mass must be a positive number of kilograms"),
        ))
    }
}

/// Checks a URDF link's mass (kg): positive, or zero together with a zero
/// inertia tensor (URDFs mark pure frames, such as tool flanges, that way;
/// Pinocchio accepts them).
///
/// # Errors
/// A diagnostic at `location` naming `what`.
pub fn check_link_mass(mass: f64, inertia: &Mat3, what: &str, location: &Location) -> Result<()> {
    if mass == 0.0 && inertia.iter().flatten().all(|x| *x == 0.0) {
        return Ok(());
    }
    check_mass(mass, what, location).map_err(|mut d| {
        if mass == 0.0 {
            d.message
                .push_str(" (a massless frame must also have a zero inertia tensor)");
        }
        d
    })
}

/// Checks a rotational inertia about the centre of mass (kg m²): finite,
/// symmetric, positive semi-definite (a point mass has zero inertia), and its
/// principal moments obey the triangle inequality `I1 + I2 >= I3`, which
/// every real mass distribution satisfies.
///
/// # Errors
/// A diagnostic at `location` naming `what` and the violated property.
pub fn check_rotational_inertia(inertia: &Mat3, what: &str, location: &Location) -> Result<()> {
    let fail = |why: String| Err(Diagnostic::error(location.clone(), format!("{what} {why}")));
    if inertia.iter().flatten().any(|x| !x.is_finite()) {
        return fail("has a non-finite inertia entry".into());
    }
    let scale = inertia
        .iter()
        .flatten()
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    let tol = RELATIVE_TOLERANCE * scale;
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        if (inertia[i][j] - inertia[j][i]).abs() > tol {
            return fail(format!(
                "has an inertia matrix that is not symmetric: entry ({i}, {j}) is {} but ({j}, {i}) is {}",
                inertia[i][j], inertia[j][i]
            ));
        }
    }
    let e = symmetric_eigenvalues(inertia);
    if e[0] < -tol {
        return fail(format!(
            "has an inertia matrix that is not positive semi-definite (principal moments {:.6e}, {:.6e}, {:.6e} kg m²)",
            e[0], e[1], e[2]
        ));
    }
    if e[0] + e[1] < e[2] - tol {
        return fail(format!(
            "has principal moments of inertia {:.6e}, {:.6e}, {:.6e} kg m² that break the triangle inequality (the two smaller must add up to at least the largest)",
            e[0], e[1], e[2]
        ));
    }
    Ok(())
}

/// What a rotational inertia about the centre of mass breaks, if anything,
/// with tolerances relative to the tensor's scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TensorProblem {
    /// Principal moments (ascending, kg m²) with a negative one beyond
    /// rounding: no mass distribution has it, and a moving body with it
    /// can make the mass matrix indefinite.
    NotPositiveSemiDefinite([f64; 3]),
    /// Principal moments whose two smaller add up to less than the largest
    /// beyond rounding: no real body has it, but the dynamics are still
    /// well defined (Pinocchio accepts it).
    BreaksTriangleInequality([f64; 3]),
}

/// Inertia below which a tensor's entries are rounding noise of a zero
/// tensor (kg m²): iCub writes a massless frame's tensor as ±5e-20.
const NOISE_FLOOR: f64 = 1e-15;

/// The problem of a finite, symmetric tensor, if any: a negative principal
/// moment below `−10⁻⁶` of the largest magnitude (and below the noise
/// floor of 1e-15 kg m²), or a triangle-inequality deficit beyond that.
#[must_use]
pub fn tensor_problem(inertia: &Mat3) -> Option<TensorProblem> {
    let scale = inertia
        .iter()
        .flatten()
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    let tol = (RELATIVE_TOLERANCE * scale).max(NOISE_FLOOR);
    let e = symmetric_eigenvalues(inertia);
    if e[0] < -tol {
        Some(TensorProblem::NotPositiveSemiDefinite(e))
    } else if e[0] + e[1] < e[2] - tol {
        Some(TensorProblem::BreaksTriangleInequality(e))
    } else {
        None
    }
}

impl TensorProblem {
    /// The sentence for a diagnostic, after "`what` ".
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Self::NotPositiveSemiDefinite(e) => format!(
                "has an inertia matrix that is not positive semi-definite (principal moments {:.6e}, {:.6e}, {:.6e} kg m²)",
                e[0], e[1], e[2]
            ),
            Self::BreaksTriangleInequality(e) => format!(
                "has principal moments of inertia {:.6e}, {:.6e}, {:.6e} kg m² that break the triangle inequality (the two smaller must add up to at least the largest)",
                e[0], e[1], e[2]
            ),
        }
    }
}

/// Checks that every moving joint moves something: a joint whose whole
/// subtree has neither mass nor rotational inertia makes the mass matrix
/// singular.
///
/// # Errors
/// A diagnostic at the offending joint.
pub fn check_subtrees_have_mass(model: &ModelDescription) -> Result<()> {
    // Mass, or a rotational inertia on a massless link (Pinocchio keeps
    // one): either gives the joint something to move.
    let mut subtree = model
        .bodies
        .iter()
        .map(|b| {
            let i = &b.inertia.inertia;
            b.inertia.mass + i[0][0] + i[1][1] + i[2][2]
        })
        .collect::<Vec<_>>();
    for i in (0..model.bodies.len()).rev() {
        if let Some(p) = model.bodies[i].parent {
            subtree[p] += subtree[i];
        }
    }
    for (body, mass) in model.bodies.iter().zip(subtree) {
        if mass <= 0.0 {
            return Err(Diagnostic::error(
                body.location.clone(),
                format!(
                    "joint `{}` moves only links without mass or inertia (`{}` and everything below it); its row of the mass matrix would be zero",
                    body.joint_name, body.name
                ),
            ));
        }
    }
    Ok(())
}
