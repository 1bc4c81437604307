//! The probe tables beyond the algorithms on the Panda and Solo12: the
//! planar algorithms, the drives and sensitivities, the public formulas,
//! the simulation and the model updates.

pub mod drives;
pub mod formulas;
pub mod planar;
pub mod sim;
pub mod update;
