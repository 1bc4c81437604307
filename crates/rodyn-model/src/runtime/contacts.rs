//! Dynamics under rigid contacts (Pinocchio's `constraintDynamics`) and
//! impacts (`impulseDynamics`), contacts named by frame.

use super::padded::MAX_CONTACT_ROWS;
use super::{RuntimeError, RuntimeModel, Workspace};
use rodyn::algorithm::constrained_dynamics::{
    constrained_forward_dynamics, impulse_dynamics, ConstraintSettings, Contact,
};
use rodyn::spatial::{Transform, Vec3};
use rodyn::Frame;

/// Most contacts of one call: point contacts, three rows each.
const MAX_CONTACTS: usize = MAX_CONTACT_ROWS / 3;

/// A contact held rigidly, by the name of its frame.
///
/// No Baumgarte stabilisation is applied (Pinocchio's default contact
/// models): the contact's acceleration is held at zero, so where it is
/// held plays no part.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ContactSpec {
    /// The frame's origin held: three rows, `λ` a force (N) in world axes
    /// at the point (Pinocchio's `CONTACT_3D` in `LOCAL_WORLD_ALIGNED`).
    Point {
        /// The frame's name.
        frame: String,
    },
    /// The whole frame held: six rows, `λ` the force (N) then the moment
    /// (N m) in the frame's own axes about its origin (Pinocchio's
    /// `CONTACT_6D` in `LOCAL`).
    Frame {
        /// The frame's name.
        frame: String,
    },
}

impl ContactSpec {
    /// A point contact at `frame`'s origin.
    #[must_use]
    pub fn point(frame: impl Into<String>) -> Self {
        Self::Point {
            frame: frame.into(),
        }
    }

    /// A contact holding the whole `frame`.
    #[must_use]
    pub fn frame(frame: impl Into<String>) -> Self {
        Self::Frame {
            frame: frame.into(),
        }
    }

    /// Constrained rows (entries of `λ`): 3 or 6.
    #[must_use]
    pub fn rows(&self) -> usize {
        match self {
            Self::Point { .. } => 3,
            Self::Frame { .. } => 6,
        }
    }
}

/// The number of `λ` entries `contacts` produce (3 per point, 6 per frame).
#[must_use]
pub fn contact_rows(contacts: &[ContactSpec]) -> usize {
    contacts.iter().map(ContactSpec::rows).sum()
}

impl RuntimeModel {
    /// `contacts` as rodyn's, in a fixed array (no allocation per call).
    fn held(
        &self,
        contacts: &[ContactSpec],
    ) -> Result<([Contact<f64>; MAX_CONTACTS], usize), RuntimeError> {
        let rows = contact_rows(contacts);
        if rows > MAX_CONTACT_ROWS {
            return Err(RuntimeError::invalid_input(format!(
                "contacts have {rows} rows, more than the {MAX_CONTACT_ROWS} a run-time call takes"
            )));
        }
        let unused = Contact::point(Frame::new(0, Transform::IDENTITY), Vec3::ZERO);
        let mut held = [unused; MAX_CONTACTS];
        for (slot, c) in held.iter_mut().zip(contacts) {
            *slot = match c {
                ContactSpec::Point { frame } => Contact::point(*self.frame(frame)?, Vec3::ZERO),
                ContactSpec::Frame { frame } => {
                    Contact::frame(*self.frame(frame)?, Transform::IDENTITY)
                }
            };
        }
        Ok((held, contacts.len()))
    }

    fn check_lambda(
        &self,
        name: &str,
        contacts: &[ContactSpec],
        out: &[f64],
    ) -> Result<(), RuntimeError> {
        let rows = contact_rows(contacts);
        if out.len() == rows {
            Ok(())
        } else {
            Err(RuntimeError::invalid_input(format!(
                "{name} has {} entries, the contacts have {rows} rows (3 per point, 6 per frame)",
                out.len()
            )))
        }
    }

    /// Forward dynamics with `contacts` held: `q̈` into `ddq_out` and the
    /// contact forces into `lambda_out` (in `contacts`' order, 3 entries
    /// per point and 6 per frame contact, see [`ContactSpec`]), by the KKT
    /// system (Pinocchio's `constraintDynamics`).
    ///
    /// # Errors
    /// An unknown frame, more than [`MAX_CONTACT_ROWS`] rows, redundant
    /// contacts; as [`aba`](Self::aba).
    #[allow(clippy::too_many_arguments)]
    pub fn constrained_dynamics(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        contacts: &[ContactSpec],
        ddq_out: &mut [f64],
        lambda_out: &mut [f64],
    ) -> Result<(), RuntimeError> {
        let settings = ConstraintSettings::default();
        class_call!(self, ws, "constrained dynamics",
        inputs: [q, "v" => v, "tau" => tau],
        checks: [
            self.check_nv("ddq_out", ddq_out),
            self.check_lambda("lambda_out", contacts, lambda_out),
        ],
        let (held, n) = self.held(contacts)?;
        |m, s| constrained_forward_dynamics(
            &m.model, &mut s.data, &mut s.constraint, &s.q, &s.v, &s.a, &held[..n], &settings,
        )
        .map(|(ddq, lambda)| {
            ddq_out.copy_from_slice(&ddq[..ddq_out.len()]);
            lambda_out.copy_from_slice(lambda);
        }))
    }

    /// The velocity just after an impact of `contacts` at `q`, arriving
    /// with `v_before`: `v⁺` into `v_after` and the impulses (N s, N m s;
    /// axes as [`constrained_dynamics`](Self::constrained_dynamics)'s `λ`)
    /// into `impulses`; `restitution` in `[0, 1]` (Pinocchio's
    /// `impulseDynamics`).
    ///
    /// # Errors
    /// As [`constrained_dynamics`](Self::constrained_dynamics); a
    /// restitution outside `[0, 1]`.
    #[allow(clippy::too_many_arguments)]
    pub fn impulse_dynamics(
        &self,
        ws: &mut Workspace,
        q: &[f64],
        v_before: &[f64],
        contacts: &[ContactSpec],
        restitution: f64,
        v_after: &mut [f64],
        impulses: &mut [f64],
    ) -> Result<(), RuntimeError> {
        class_call!(self, ws, "impulse dynamics",
        inputs: [q, "v_before" => v_before],
        checks: [
            self.check_nv("v_after", v_after),
            self.check_lambda("impulses", contacts, impulses),
            check_restitution(restitution),
        ],
        let (held, n) = self.held(contacts)?;
        |m, s| impulse_dynamics(
            &m.model, &mut s.data, &mut s.constraint, &s.q, &s.v, &held[..n], restitution, 0.0,
        )
        .map(|(v_plus, lambda)| {
            v_after.copy_from_slice(&v_plus[..v_after.len()]);
            impulses.copy_from_slice(lambda);
        }))
    }
}

/// `Ok` for a coefficient of restitution in `[0, 1]`.
fn check_restitution(restitution: f64) -> Result<(), RuntimeError> {
    if (0.0..=1.0).contains(&restitution) {
        Ok(())
    } else {
        Err(RuntimeError::invalid_input(format!(
            "restitution is {restitution}, it must be in [0, 1]"
        )))
    }
}
