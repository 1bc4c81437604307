//! Two copies of a model: the active one that the control tick reads, and
//! a staging one that the next model is written into, published between
//! two ticks by one atomic store.

use super::ModelUpdate;
use crate::error::Result;
use crate::model::Model;
use crate::space::Space;
use crate::Scalar;
use core::cell::UnsafeCell;
use core::sync::atomic::{AtomicU8, Ordering};

/// The value of [`DoubleBuffered::reading`] when the reader holds no copy.
const NOT_READING: u8 = 0;

/// An active model and a staging copy (any `M`, usually a
/// [`Model`]), shared by one [`Reader`] (the control tick) and one
/// [`Writer`] (whatever prepares updates), which
/// [`split`](Self::split) hands out.
///
/// # The context it assumes
///
/// A single-core microcontroller whose control tick runs in an interrupt
/// (a timer's, or an RTIC or Embassy task) at a *higher* priority than
/// the context that writes updates (the main loop, a background task):
/// the tick can interrupt the writer at any instruction, the writer never
/// interrupts a tick, and a tick runs to its end. The tick reads through
/// [`Reader::read`], the writer stages with [`Writer::stage`] and
/// publishes with [`Writer::publish`].
///
/// # Why the tick never sees a half-written model, and never waits
///
/// Two atomics guard the two copies: `active` names the copy a read
/// starts on (only the writer stores it, by [`Writer::publish`]), and
/// `reading` names the copy the reader is in (only the reader stores it).
///
/// * A read loads `active`, announces that copy in `reading`, loads
///   `active` again and reads that copy only when it is still the active
///   one; when a publish came in between it starts over on the new one.
///   It holds the copy until its closure returns and then clears
///   `reading`. It takes no lock.
/// * The writer writes only the copy that `active` does not name, and
///   before writing it waits until `reading` does not name it.
/// * Publishing is one store of `active`; the copy that was active stays
///   as it is until the writer stages again.
///
/// Every access to the two atomics is sequentially consistent, so they fall in one
/// order that every context sees. A reader that announced the staging
/// copy (having loaded `active` just before a publish) either announced
/// it before the writer looked, and the writer waits, or after, and then
/// its second load comes after the publish and it starts over without
/// touching the copy. The writer's writes happen before the reads of the
/// tick that loads the published `active` (release and acquire), and the
/// reads of a tick happen before the writes of a later staging (the
/// clearing of `reading` and the writer's load of it). A data race on a
/// copy is therefore impossible with any number of cores and any
/// priorities; that part is checked by Miri on threads (`cargo xtask
/// lint`). Under the single-core assumption above the waits vanish: the
/// writer cannot run while a tick holds a copy, so it never waits, and no
/// publish can come between a tick's two loads, so a tick never starts
/// over. Where a reader and a writer run on two cores, the tick may start
/// over (once per publish that races it) and the writer may wait for a
/// tick to end.
///
/// A tick reads the model that was active when it started, whole, even
/// when a publish comes while it runs; the next tick reads the new one.
///
/// # Example
///
/// ```
/// use rodyn::algorithm::rnea::gravity_torques;
/// use rodyn::frame::Frame;
/// use rodyn::update::{DoubleBuffered, ModelUpdate, ParameterChange};
/// # use rodyn::prelude::*;
/// # // A 1 kg point mass on a massless 1 m link, pivot about z, gravity -y.
/// # const PENDULUM: Model<f64, 1, 1, 1> = Model::new(
/// #     [None], [Joint::revolute(Axis::Z)], [Transform::IDENTITY],
/// #     [Inertia::point_mass(1.0, Vec3::new(1.0, 0.0, 0.0))],
/// #     Motion::new(Vec3::ZERO, Vec3::new(0.0, -9.81, 0.0)),
/// # );
/// let mut models = DoubleBuffered::new(PENDULUM);
/// let (mut tick, mut updates) = models.split();
/// let mut data = Data::new();
/// // The tick (an interrupt, in firmware): gravity torque at q = 0.
/// let mut hold = |tick: &mut rodyn::update::Reader<'_, _>| {
///     tick.read(|model| gravity_torques(model, &mut data, &[0.0]).map(|tau| tau[0]))
/// };
/// assert!((hold(&mut tick)? - 9.81).abs() < 1e-12);
/// // The main loop: a 0.5 kg payload at the tip, staged and not yet published.
/// let tip = Frame::new(0, Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)));
/// let payload = Inertia::point_mass(0.5, Vec3::ZERO);
/// updates.stage_update(&ModelUpdate::new([ParameterChange::Payload { frame: tip, inertia: payload }]))?;
/// assert!((hold(&mut tick)? - 9.81).abs() < 1e-12);
/// assert!(updates.publish());
/// assert!((hold(&mut tick)? - 1.5 * 9.81).abs() < 1e-12);
/// // A NaN mass is refused when staged; nothing is published.
/// let bad = ModelUpdate::new([ParameterChange::Payload { frame: tip, inertia: Inertia::point_mass(f64::NAN, Vec3::ZERO) }]);
/// assert!(updates.stage_update(&bad).is_err());
/// assert!(!updates.publish());
/// assert!((hold(&mut tick)? - 1.5 * 9.81).abs() < 1e-12);
/// # Ok::<(), rodyn::Error>(())
/// ```
#[derive(Debug)]
pub struct DoubleBuffered<M> {
    copies: [UnsafeCell<M>; 2],
    /// The copy a read starts on: 0 or 1.
    active: AtomicU8,
    /// The copy the reader is in, plus one; [`NOT_READING`] between reads.
    reading: AtomicU8,
}

// SAFETY: the copies are reached only through `Reader::read` (shared
// references, in the reader's context, so `M: Sync`) and `Writer::stage`
// (a unique reference to the copy no read is in, written in the writer's
// context and read in the reader's, so `M: Send`); the protocol on the
// type's documentation keeps the two apart.
unsafe impl<M: Send + Sync> Sync for DoubleBuffered<M> {}

impl<M: Clone> DoubleBuffered<M> {
    /// Both copies equal to `model`; the first is active. `const`, so it
    /// can initialise a `static`.
    #[must_use]
    pub const fn new(model: M) -> Self
    where
        M: Copy,
    {
        Self {
            copies: [UnsafeCell::new(model), UnsafeCell::new(model)],
            active: AtomicU8::new(0),
            reading: AtomicU8::new(NOT_READING),
        }
    }

    /// The active copy, while no [`Reader`] or [`Writer`] exists.
    #[must_use]
    pub fn active(&self) -> &M {
        let active = usize::from(self.active.load(Ordering::SeqCst) & 1);
        // SAFETY: `&self` while the handles, which borrow `self` mutably,
        // are gone: nothing writes either copy.
        unsafe { &*self.copies[active].get() }
    }

    /// The handle of the control tick and the handle of the context that
    /// prepares updates. Each is `Send`, to be moved to its context; there
    /// is one of each while they live.
    pub fn split(&mut self) -> (Reader<'_, M>, Writer<'_, M>) {
        let buffers: &Self = self;
        (
            Reader { buffers },
            Writer {
                buffers,
                staged: false,
            },
        )
    }
}

/// The control tick's handle on a [`DoubleBuffered`]: reads the active
/// copy.
#[derive(Debug)]
pub struct Reader<'a, M> {
    buffers: &'a DoubleBuffered<M>,
}

/// Clears `reading` when a read ends, also when its closure panics (on a
/// host), so that the writer is not left waiting.
struct EndOfRead<'a>(&'a AtomicU8);

impl Drop for EndOfRead<'_> {
    fn drop(&mut self) {
        self.0.store(NOT_READING, Ordering::SeqCst);
    }
}

impl<M> Reader<'_, M> {
    /// Calls `tick` with the copy that is active when the read starts, and
    /// returns its result. A publish while `tick` runs takes effect at the
    /// next read. Never waits on the writer (see [`DoubleBuffered`]).
    pub fn read<R>(&mut self, tick: impl FnOnce(&M) -> R) -> R {
        let buffers = self.buffers;
        let active = loop {
            let active = buffers.active.load(Ordering::SeqCst);
            buffers.reading.store(active + 1, Ordering::SeqCst);
            // A publish between the load and the announcement: the writer
            // may already be in the copy announced; take the new one.
            if buffers.active.load(Ordering::SeqCst) == active {
                break usize::from(active & 1);
            }
        };
        let _end = EndOfRead(&buffers.reading);
        // SAFETY: `reading` names this copy and it was still the active one
        // after the announcement, so the writer (which writes only the copy
        // `active` does not name, and not while `reading` names it) does
        // not write it until `_end` clears `reading`.
        tick(unsafe { &*buffers.copies[active].get() })
    }
}

/// The handle of the context that prepares updates: writes the staging
/// copy and publishes it.
#[derive(Debug)]
pub struct Writer<'a, M> {
    buffers: &'a DoubleBuffered<M>,
    /// `true` once a staging has passed and until it is published.
    staged: bool,
}

impl<M: Clone> Writer<'_, M> {
    /// The copy the ticks read now.
    #[must_use]
    pub fn active(&self) -> &M {
        let active = usize::from(self.buffers.active.load(Ordering::SeqCst) & 1);
        // SAFETY: only this writer writes a copy, and only in `stage`,
        // which needs `&mut self` (so no `&M` from here is alive), and never
        // the active one; readers only read.
        unsafe { &*self.buffers.copies[active].get() }
    }

    /// Makes the staging copy a copy of the active model, lets `update`
    /// change it, and marks it ready to [`publish`](Self::publish) when
    /// `update` returns `Ok`. On an error the staging copy is not
    /// published, and the active model, which the ticks keep reading, is
    /// untouched. Waits only for a read of the staging copy that began
    /// before the last publish, which on a single core cannot be running
    /// (see [`DoubleBuffered`]).
    ///
    /// # Errors
    /// `update`'s.
    pub fn stage<R>(&mut self, update: impl FnOnce(&mut M) -> Result<R>) -> Result<R> {
        let buffers = self.buffers;
        // Only this writer stores `active`.
        let active = buffers.active.load(Ordering::SeqCst) & 1;
        let staging = 1 - active;
        self.staged = false;
        while buffers.reading.load(Ordering::SeqCst) == staging + 1 {
            core::hint::spin_loop();
        }
        // SAFETY: the staging copy is not the active one, so no read can
        // start on it (`Reader::read` checks `active` after announcing), and
        // no read is in it (`reading` does not name it, as just loaded).
        // The active copy is only read, here as by the reader.
        let (copy, current) = unsafe {
            (
                &mut *buffers.copies[usize::from(staging)].get(),
                &*buffers.copies[usize::from(active)].get(),
            )
        };
        copy.clone_from(current);
        let result = update(copy)?;
        self.staged = true;
        Ok(result)
    }

    /// Makes the staged copy the active one: ticks that start from now on
    /// read it. Returns `false`, publishing nothing, when no staging has
    /// passed since the last publish.
    pub fn publish(&mut self) -> bool {
        if !self.staged {
            return false;
        }
        self.staged = false;
        let active = self.buffers.active.load(Ordering::SeqCst) & 1;
        self.buffers.active.store(1 - active, Ordering::SeqCst);
        true
    }

    /// `true` when a staged copy waits to be published.
    #[must_use]
    pub const fn is_staged(&self) -> bool {
        self.staged
    }
}

impl<S: Scalar, const NB: usize, const NQ: usize, const NV: usize, G: Space>
    Writer<'_, Model<S, NB, NQ, NV, G>>
{
    /// [`stage`](Self::stage)s a batch of parameter changes: writes them
    /// into the staging copy, which is published only if every change
    /// passes ([`ModelUpdate::write_into`]).
    ///
    /// # Errors
    /// The first failing change's, naming the body, coordinate or
    /// parameter; the staging copy is then not published.
    pub fn stage_update<const N: usize>(&mut self, update: &ModelUpdate<S, N, G>) -> Result<()> {
        self.stage(|staging| update.write_into(staging))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::{Error, Quantity};
    extern crate std;

    /// A reader on one thread and a writer on another: every read sees a
    /// copy whose entries were all written by one staging (never a mix),
    /// and the versions it sees never go back. Run under Miri (`cargo
    /// xtask lint`), which reports any data race on the copies.
    #[test]
    fn reads_see_whole_copies_while_a_writer_publishes() {
        let rounds = crate::test_points(2_000, 40) as u64;
        let mut buffers = DoubleBuffered::new([0u64; 16]);
        let (mut reader, mut writer) = buffers.split();
        std::thread::scope(|scope| {
            scope.spawn(move || {
                for version in 1..=rounds {
                    writer
                        .stage(|copy| {
                            for entry in copy.iter_mut() {
                                *entry = version;
                            }
                            Ok(())
                        })
                        .unwrap();
                    assert!(writer.publish());
                }
            });
            let mut last = 0;
            while last < rounds {
                let (first, whole) =
                    reader.read(|copy| (copy[0], copy.iter().all(|e| *e == copy[0])));
                assert!(whole, "a read saw a half-written copy");
                assert!(
                    first >= last,
                    "a read went back from version {last} to {first}"
                );
                last = first;
            }
        });
        assert_eq!(buffers.active(), &[rounds; 16]);
    }

    /// A staging that fails is not published: the reader keeps the active
    /// copy, and the next good staging starts again from that copy.
    #[test]
    fn a_failed_staging_publishes_nothing() {
        let mut buffers = DoubleBuffered::new([1.0f64; 3]);
        let (mut reader, mut writer) = buffers.split();
        let refused = writer.stage(|copy| {
            copy[0] = 2.0;
            Err::<(), _>(Error::NonFinite {
                quantity: Quantity::ModelParameter,
                index: 1,
            })
        });
        assert!(refused.is_err());
        assert!(!writer.is_staged());
        assert!(!writer.publish());
        assert_eq!(reader.read(|copy| *copy), [1.0; 3]);
        writer
            .stage(|copy| {
                copy[2] = 3.0;
                Ok(())
            })
            .unwrap();
        // Staged, not yet published: the tick still reads the old copy.
        assert_eq!(reader.read(|copy| *copy), [1.0; 3]);
        assert!(writer.publish());
        assert_eq!(reader.read(|copy| *copy), [1.0, 1.0, 3.0]);
        assert_eq!(writer.active(), &[1.0, 1.0, 3.0]);
    }
}
