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

/// `FromStr` (a number, then the type's `new` check) and `Display` for a
/// checked number type wrapping an `f64`, so that every such argument
/// parses and prints alike.
macro_rules! checked_number {
    ($type:ident) => {
        impl core::str::FromStr for $type {
            type Err = String;

            fn from_str(s: &str) -> Result<Self, String> {
                let x: f64 = s
                    .trim()
                    .parse()
                    .map_err(|_| format!("`{s}` is not a number"))?;
                Self::new(x)
            }
        }

        impl core::fmt::Display for $type {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                self.0.fmt(f)
            }
        }
    };
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
