//! On-line model updates as transactions: a validated batch of parameter
//! changes that applies whole or not at all, and a double buffer that lets
//! a control tick keep reading one model while the next is written.
//!
//! | item                  | file                 | what it is                                                   |
//! |-----------------------|----------------------|--------------------------------------------------------------|
//! | [`ParameterChange`]   | `change.rs`          | one change: a body's inertia, a payload at a frame, an armature, a motor, a placement, gravity |
//! | [`ModelUpdate`]       | `batch.rs`           | a fixed-size batch of changes, validated as one              |
//! | [`DoubleBuffered`]    | `double_buffered.rs` | the active model and a staging copy, published between ticks |
//!
//! A batch is checked by the model's own validated setters
//! ([`Model::set_inertia`](crate::Model::set_inertia) and its siblings), in
//! order, on a copy: a batch that fails at its k-th change returns that
//! change's error (naming the body, the velocity coordinate or the
//! parameter, as the setter does) and the model it was given is unchanged,
//! bit for bit; a batch that passes leaves exactly the model the same
//! setters would have left.
//!
//! # Between two ticks
//!
//! [`DoubleBuffered`] holds two copies of a model. The control tick reads
//! the *active* one through a [`Reader`]; a lower-priority context (the
//! main loop, a background task) writes the next model into the other, the
//! *staging* copy, through a [`Writer`], and publishes it with one atomic
//! store. A tick that starts after the store reads the new model; one that
//! started before reads the old one to its end. The tick never takes a
//! lock and never waits for the writer. The arrangement and why it is
//! sound are on [`DoubleBuffered`].

mod batch;
mod change;
mod double_buffered;

pub use batch::ModelUpdate;
pub use change::ParameterChange;
pub use double_buffered::{DoubleBuffered, Reader, Writer};
