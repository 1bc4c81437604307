//! A forward-mode dual number: `re + du ε` with `ε² = 0`.
//!
//! Running an algorithm on `Dual` with one input's `du` set to 1 returns, in
//! every output's `du`, the derivative of that output with respect to that
//! input: exact to rounding, no step size to choose. `no_std` and `Copy`.

use super::Scalar;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A value with one directional derivative.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Dual {
    /// The value.
    pub re: f64,
    /// The derivative along the chosen direction.
    pub du: f64,
}

impl Dual {
    /// A constant: derivative zero.
    #[must_use]
    pub const fn constant(re: f64) -> Self {
        Self { re, du: 0.0 }
    }
    /// The independent variable: derivative one.
    #[must_use]
    pub const fn variable(re: f64) -> Self {
        Self { re, du: 1.0 }
    }
    /// Applies a scalar function with known derivative `df` at `re`.
    #[inline]
    fn chain(self, f: f64, df: f64) -> Self {
        Self {
            re: f,
            du: df * self.du,
        }
    }
}

impl PartialOrd for Dual {
    /// Orders by value only, so branches in generic code follow the value.
    #[inline]
    fn partial_cmp(&self, other: &Self) -> Option<core::cmp::Ordering> {
        self.re.partial_cmp(&other.re)
    }
}

impl Add for Dual {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self {
            re: self.re + o.re,
            du: self.du + o.du,
        }
    }
}
impl Sub for Dual {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self {
            re: self.re - o.re,
            du: self.du - o.du,
        }
    }
}
impl Mul for Dual {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        Self {
            re: self.re * o.re,
            du: self.du * o.re + self.re * o.du,
        }
    }
}
impl Div for Dual {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        let inv = 1.0 / o.re;
        Self {
            re: self.re * inv,
            du: (self.du * o.re - self.re * o.du) * inv * inv,
        }
    }
}
impl Neg for Dual {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self {
            re: -self.re,
            du: -self.du,
        }
    }
}
macro_rules! assign_op {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for Dual {
            #[inline]
            fn $f(&mut self, o: Self) {
                *self = *self $op o;
            }
        }
    };
}
assign_op!(AddAssign, add_assign, +);
assign_op!(SubAssign, sub_assign, -);
assign_op!(MulAssign, mul_assign, *);
assign_op!(DivAssign, div_assign, /);

impl Scalar for Dual {
    const ZERO: Self = Self::constant(0.0);
    const ONE: Self = Self::constant(1.0);
    const NEG_ONE: Self = Self::constant(-1.0);
    const EPSILON: f64 = f64::EPSILON;

    #[inline]
    fn from_f64(value: f64) -> Self {
        Self::constant(value)
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self.re
    }
    #[inline]
    fn sqrt(self) -> Self {
        let r = Scalar::sqrt(self.re);
        // d sqrt(x) = dx / (2 sqrt(x)); at 0 the derivative is infinite unless dx = 0.
        let du = if self.du == 0.0 {
            0.0
        } else {
            self.du / (2.0 * r)
        };
        Self { re: r, du }
    }
    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        let (s, c) = Scalar::sin_cos(self.re);
        (self.chain(s, c), self.chain(c, -s))
    }
    #[inline]
    fn atan2(self, x: Self) -> Self {
        let r2 = self.re * self.re + x.re * x.re;
        Self {
            re: Scalar::atan2(self.re, x.re),
            du: (x.re * self.du - self.re * x.du) / r2,
        }
    }
    #[inline]
    fn exp(self) -> Self {
        let e = Scalar::exp(self.re);
        self.chain(e, e)
    }
    #[inline]
    fn ln(self) -> Self {
        self.chain(Scalar::ln(self.re), 1.0 / self.re)
    }
    #[inline]
    fn tanh(self) -> Self {
        let t = Scalar::tanh(self.re);
        self.chain(t, 1.0 - t * t)
    }
    #[inline]
    fn abs(self) -> Self {
        if self.re < 0.0 {
            -self
        } else {
            self
        }
    }
    #[inline]
    fn is_finite(self) -> bool {
        Scalar::is_finite(self.re) && Scalar::is_finite(self.du)
    }
}
