//! Numbers in messages.

/// `x` as a message shows it: plain when of everyday size, in exponent
/// form when huge or tiny (so `1e300` is not three hundred digits).
#[must_use]
pub fn shown(x: f64) -> String {
    let size = x.abs();
    if size == 0.0 || !x.is_finite() || (1e-3..1e6).contains(&size) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::shown;

    #[test]
    fn plain_when_everyday_exponent_otherwise() {
        assert_eq!(shown(5.0), "5");
        assert_eq!(shown(0.0005), "5e-4");
        assert_eq!(shown(1e300), "1e300");
        assert_eq!(shown(-2.5e7), "-2.5e7");
        assert_eq!(shown(f64::NAN), "NaN");
        assert_eq!(shown(0.0), "0");
    }
}
