//! An arm's encoders and torque drives wired to the simulated signals, as
//! every Panda example connects them.

use super::{Signals, SimulatedEncoderSpi, SimulatedPwm};
use crate::drivers::{AbsoluteEncoder, TorqueDrive};

/// The encoders and drives of an `N`-joint arm on `signals`: encoder k
/// mounted with its zero at `offsets[k]` counts (and its driver told so),
/// drive k with full scale `limits[k]` (N m).
pub type Wiring<'s, const N: usize> = (
    [AbsoluteEncoder<SimulatedEncoderSpi<'s>>; N],
    [TorqueDrive<SimulatedPwm<'s>>; N],
);

/// See [`Wiring`].
#[must_use]
pub fn wire<const N: usize>(
    signals: &Signals<N>,
    offsets: [u32; N],
    limits: [f32; N],
) -> Wiring<'_, N> {
    (
        core::array::from_fn(|k| {
            AbsoluteEncoder::new(
                SimulatedEncoderSpi::new(&signals.angles[k], offsets[k]),
                offsets[k],
            )
        }),
        core::array::from_fn(|k| {
            TorqueDrive::new(SimulatedPwm::new(&signals.duties[k]), limits[k])
        }),
    )
}
