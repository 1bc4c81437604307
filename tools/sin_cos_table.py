#!/usr/bin/env python3
"""Prints the body of `MULTIPLES_OF_PI_OVER_64` in
crates/rodyn/src/scalar/sin_cos_f64.rs: the sine and cosine of k pi/64 for
k = 0..128, each correctly rounded to a double (mpmath at 300 bits; exact
zeros where the value is zero).

    pip install mpmath
    python3 tools/sin_cos_table.py
"""
import mpmath

mpmath.mp.prec = 300


def rounded(value):
    """The double nearest `value`, with a true zero as 0.0."""
    return 0.0 if abs(value) < mpmath.mpf("1e-60") else float(value)


for k in range(128):
    angle = mpmath.mpf(k) * mpmath.pi / 64
    s, c = rounded(mpmath.sin(angle)), rounded(mpmath.cos(angle))
    print(f"    [{s!r}, {c!r}],")
