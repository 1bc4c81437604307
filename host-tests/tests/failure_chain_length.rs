//! Failure map 1: f32 against f64 on long chains. ABA stays accurate in f32
//! up to 120 links; CRBA's f32 mass matrix grows so ill-conditioned on long
//! chains that its solution loses every digit but the first, while staying
//! finite.

use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::prelude::*;

/// A 3-D chain of N links, total 1 m and 1 kg, hanging along -z, joints
/// alternating about y and x (the same chain as `rodyn-sim failures chain`).
fn chain<S: Scalar, const N: usize>() -> Model<S, N, N, N> {
    let l = 1.0 / N as f64;
    let m = 1.0 / N as f64;
    let across = m * l * l / 12.0;
    let f = S::from_f64;
    let link = Inertia::new(
        f(m),
        Vec3::new(S::ZERO, S::ZERO, f(-l / 2.0)),
        Sym3::diagonal(f(across), f(across), f(across * 0.01)),
    );
    Model::new(
        core::array::from_fn(|i| i.checked_sub(1)),
        core::array::from_fn(|i| Joint::revolute(if i % 2 == 0 { Axis::Y } else { Axis::X })),
        core::array::from_fn(|i| {
            Transform::from_translation(Vec3::new(
                S::ZERO,
                S::ZERO,
                if i == 0 { S::ZERO } else { f(-l) },
            ))
        }),
        [link; N],
        Motion::new(Vec3::ZERO, Vec3::new(S::ZERO, S::ZERO, f(-9.81))),
    )
}

/// Relative f32 error of method F on an N-link chain, or rodyn's error.
fn f32_error<F: ForwardDynamics, const N: usize>() -> Result<f64, Error> {
    let q: [f64; N] = core::array::from_fn(|k| 0.4 * (1.3 * k as f64 + 0.2).sin());
    let v: [f64; N] = core::array::from_fn(|k| 0.5 * (0.7 * k as f64).cos());
    let reference = *Aba::forward_dynamics(
        &chain::<f64, N>(),
        &mut Box::new(Data::new()),
        &q,
        &v,
        &[0.0; N],
        None,
    )?;
    let a = *F::forward_dynamics(
        &chain::<f32, N>(),
        &mut Box::new(Data::new()),
        &q.map(|x| x as f32),
        &v.map(|x| x as f32),
        &[0.0; N],
        None,
    )?;
    assert!(
        a.iter().all(|x| x.is_finite()),
        "an Ok result must be finite"
    );
    let scale = reference.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    Ok(a.iter()
        .zip(&reference)
        .fold(0.0f64, |m, (a, b)| m.max((*a as f64 - b).abs()))
        / scale)
}

#[test]
fn aba_in_f32_stays_accurate_up_to_120_links() {
    for e in [
        f32_error::<Aba, 1>(),
        f32_error::<Aba, 10>(),
        f32_error::<Aba, 40>(),
        f32_error::<Aba, 120>(),
    ] {
        let e = e.expect("ABA must not fail on these chains");
        assert!(e < 1e-5, "ABA f32 relative error {e}");
    }
}

#[test]
fn crba_in_f32_degrades_with_length_and_stays_finite() {
    let short = f32_error::<Crba, 5>().unwrap();
    let medium = f32_error::<Crba, 20>().unwrap();
    assert!(short < 1e-5, "5 links: {short}");
    // Measured 2e-4 at 20 links: two orders of magnitude worse than ABA.
    assert!(medium > 1e-5 && medium < 1e-2, "20 links: {medium}");
    // At 120 links the f32 mass matrix is still positive definite pivot by
    // pivot (each against its own diagonal entry), but so ill-conditioned
    // that κ(M) ε_f32 approaches 1: the result is finite (`f32_error`
    // asserts it) and far off (measured 0.12), the accuracy section's
    // reason to use ABA for long chains in f32.
    let long = f32_error::<Crba, 120>().unwrap();
    assert!(long > 1e-2 && long < 1.0, "120 links: {long}");
}
