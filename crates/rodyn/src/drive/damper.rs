//! A linear damper along a path.

use crate::drive::derivatives::{add_tension_derivatives, DriveDerivativeState, DriveDerivatives};
use crate::drive::geometry::PointGeometry;
use crate::drive::{DriveForces, DriveState, ForceElement, Path};
use crate::error::Result;
use crate::Scalar;

/// A linear damper: `T = c L̇`. It resists lengthening and shortening alike
/// and dissipates the power `c L̇²`.
#[derive(Clone, Copy, Debug)]
pub struct LinearDamper<S: Scalar, G: PointGeometry, const K: usize> {
    /// The path the damper follows.
    pub path: Path<S, G, K>,
    /// Damping coefficient `c` (N s/m).
    pub damping: S,
}

impl<S: Scalar, G: PointGeometry, const K: usize> LinearDamper<S, G, K> {
    /// A damper of coefficient `c` (N s/m) along `path`.
    #[must_use]
    pub const fn new(path: Path<S, G, K>, damping: S) -> Self {
        Self { path, damping }
    }
}

impl<S: Scalar, G: PointGeometry, const K: usize, const NB: usize, const NV: usize>
    ForceElement<S, G, NB, NV> for LinearDamper<S, G, K>
{
    fn add_forces(
        &self,
        state: &DriveState<'_, S, G, NB, NV>,
        _w: &[S],
        out: &mut DriveForces<S, G, NB, NV>,
    ) -> Result<()> {
        let kin = self.path.kinematics(state.data)?;
        let tension = self.damping * kin.lengthening_velocity;
        self.path
            .add_tension(&kin, tension, state.data, &mut out.f_ext)
    }
    fn add_state_derivatives(
        &self,
        state: &DriveDerivativeState<'_, S, G, NB, NV>,
        _w: &[S],
        out: &mut DriveDerivatives<S, NV>,
    ) -> Result<()> {
        let path = self.path.length_derivatives(state)?;
        let tension = self.damping * path.lengthening_velocity;
        add_tension_derivatives(&path, state.v, (tension, S::ZERO, self.damping), out);
        Ok(())
    }
}
