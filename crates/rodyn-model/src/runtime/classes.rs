//! The size classes: the capacities a run-time model can take, chosen at
//! load time, and the dispatch from a model to its class's monomorphized
//! code.
//!
//! A class is a `Model<f64, NB, NQ, NV>` for one number of free-flyers `F`
//! (`NV = NB + 5 F`, `NQ = NV + F`); a file with `F` free-flyers and `n`
//! bodies goes to the smallest class of its `F` with `NB >= n`, the rest
//! filled with one-coordinate padding bodies ([`Padded`]). The capacities
//! of one `F` grow geometrically, so that the padding a file carries is a
//! bounded fraction of its bodies; the list is [`size_classes!`]'s.

use super::padded::{Padded, Scratch};
use super::skeleton::Skeleton;

/// Calls `$callback!(($args); classes…)` with every class as
/// `(Variant, F, NB, NQ, NV)`, smallest first within one `F`: the
/// geometric series with the `size-classes` feature (the tools and the
/// bindings that time their calls), otherwise one class per `F` (every
/// algorithm is there, at the largest class's cost: what a build script
/// or a drawing needs, without monomorphizing the series).
#[cfg(feature = "size-classes")]
macro_rules! size_classes {
    ($callback:ident!($($args:tt)*)) => {
        $callback! { ($($args)*);
            (Fixed1, 0, 1, 1, 1),
            (Fixed2, 0, 2, 2, 2),
            (Fixed3, 0, 3, 3, 3),
            (Fixed4, 0, 4, 4, 4),
            (Fixed5, 0, 5, 5, 5),
            (Fixed6, 0, 6, 6, 6),
            (Fixed7, 0, 7, 7, 7),
            (Fixed8, 0, 8, 8, 8),
            (Fixed9, 0, 9, 9, 9),
            (Fixed10, 0, 10, 10, 10),
            (Fixed12, 0, 12, 12, 12),
            (Fixed16, 0, 16, 16, 16),
            (Fixed20, 0, 20, 20, 20),
            (Fixed24, 0, 24, 24, 24),
            (Fixed32, 0, 32, 32, 32),
            (Fixed40, 0, 40, 40, 40),
            (Fixed48, 0, 48, 48, 48),
            (Fixed64, 0, 64, 64, 64),
            (Fixed96, 0, 96, 96, 96),
            (Fixed128, 0, 128, 128, 128),
            (Floating1, 1, 1, 7, 6),
            (Floating4, 1, 4, 10, 9),
            (Floating7, 1, 7, 13, 12),
            (Floating10, 1, 10, 16, 15),
            (Floating13, 1, 13, 19, 18),
            (Floating16, 1, 16, 22, 21),
            (Floating20, 1, 20, 26, 25),
            (Floating24, 1, 24, 30, 29),
            (Floating32, 1, 32, 38, 37),
            (Floating40, 1, 40, 46, 45),
            (Floating48, 1, 48, 54, 53),
            (Floating64, 1, 64, 70, 69),
            (Floating96, 1, 96, 102, 101),
            (Floating124, 1, 124, 130, 129),
            (TwoFloating16, 2, 16, 30, 26),
            (TwoFloating64, 2, 64, 78, 74),
        }
    };
}

#[cfg(not(feature = "size-classes"))]
macro_rules! size_classes {
    ($callback:ident!($($args:tt)*)) => {
        $callback! { ($($args)*);
            (Fixed128, 0, 128, 128, 128),
            (Floating124, 1, 124, 130, 129),
            (TwoFloating64, 2, 64, 78, 74),
        }
    };
}

macro_rules! define_classes {
    ((); $(($name:ident, $f:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {
        /// A model in its class.
        pub(super) enum ClassModel {
            $( $name(Box<Padded<$nb, $nq, $nv>>), )*
        }

        /// A workspace of one class.
        pub(super) enum ClassScratch {
            $( $name(Box<Scratch<$nb, $nq, $nv>>), )*
        }

        impl ClassModel {
            /// The smallest class that holds `skeleton`, `None` when none
            /// does; inside it, the core's checked constructor's verdict.
            pub fn new(skeleton: &Skeleton) -> Option<rodyn::Result<Self>> {
                let (nb, f) = (skeleton.nb(), skeleton.free_flyers);
                $(
                    if f == $f && nb <= $nb {
                        return Some(Padded::new(skeleton).map(Self::$name));
                    }
                )*
                None
            }

            /// A workspace for this model.
            pub fn scratch(&self) -> ClassScratch {
                match self {
                    $( Self::$name(m) => ClassScratch::$name(Scratch::new(m)), )*
                }
            }

            /// Sets the world's gravity (the linear part of `gravity`, m/s²).
            pub fn set_gravity(&mut self, gravity: rodyn::spatial::Motion<f64>) -> rodyn::Result<()> {
                match self {
                    $( Self::$name(m) => m.model.set_gravity(gravity), )*
                }
            }

            /// The class's capacities `(NB, NQ, NV)`.
            pub fn capacity(&self) -> (usize, usize, usize) {
                match self {
                    $( Self::$name(_) => ($nb, $nq, $nv), )*
                }
            }
        }

        /// The largest file each number of free-flyers fits, as
        /// `(free-flyers, bodies)`.
        pub(super) const LARGEST: &[(usize, usize)] = &[$(($f, $nb)),*];
    };
}

size_classes!(define_classes!());

/// Runs `$body` with `$m: &Padded<NB, NQ, NV>` and `$s: &mut Scratch<NB,
/// NQ, NV>` of the model's class; a workspace of another class is an
/// error.
macro_rules! dispatch {
    ($model:expr, $scratch:expr, |$m:ident, $s:ident| $body:expr) => {
        size_classes!(dispatch_arms!($model, $scratch, $m, $s, $body))
    };
}

macro_rules! dispatch_arms {
    (($model:expr, $scratch:expr, $m:ident, $s:ident, $body:expr);
     $(($name:ident, $f:literal, $nb:literal, $nq:literal, $nv:literal)),* $(,)?) => {
        match ($model, $scratch) {
            $(
                (
                    $crate::runtime::classes::ClassModel::$name($m),
                    $crate::runtime::classes::ClassScratch::$name($s),
                ) => $body,
            )*
            _ => Err($crate::runtime::RuntimeError::invalid_input(
                "the workspace belongs to another model (make it with this model's `workspace()`)",
            )),
        }
    };
}
