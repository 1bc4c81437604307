//! A planar model and its 3-D twin give the same dynamics.
//!
//! The twin has every joint about z (or along an in-plane axis), every
//! placement a rotation about z plus an x-y translation, and gravity in the
//! plane; the planar model runs on 3-component algebra. Tolerance 1e-12
//! relative in f64.

use rodyn::algorithm::crba::crba;
use rodyn::algorithm::energy::{kinetic_energy, potential_energy};
use rodyn::algorithm::forward_dynamics::{Aba, Crba, ForwardDynamics};
use rodyn::algorithm::rnea::rnea;
use rodyn::planar::Planar;
use rodyn::Data;
use rodyn_host_tests::random::{random_planar_chain, Rng};

fn close(x: f64, y: f64) -> bool {
    (x - y).abs() <= 1e-12 * (1.0 + y.abs())
}

fn check<const N: usize>(rng: &mut Rng) {
    let (planar, spatial) = random_planar_chain::<N>(rng);
    planar.validate().unwrap();
    spatial.validate().unwrap();
    let mut dp = Box::new(Data::<f64, N, N, Planar>::new());
    let mut ds = Box::new(Data::<f64, N, N>::new());
    for _ in 0..4 {
        let q: [f64; N] = rng.vector(2.0);
        let v: [f64; N] = rng.vector(2.0);
        let a: [f64; N] = rng.vector(2.0);
        let tp = *rnea(&planar, &mut dp, &q, &v, &a, None).unwrap();
        let ts = *rnea(&spatial, &mut ds, &q, &v, &a, None).unwrap();
        assert!(
            tp.iter().zip(&ts).all(|(x, y)| close(*x, *y)),
            "RNEA {tp:?} vs {ts:?}"
        );
        let mp = *crba(&planar, &mut dp, &q).unwrap();
        let ms = *crba(&spatial, &mut ds, &q).unwrap();
        for r in 0..N {
            for c in 0..N {
                assert!(
                    close(mp[r][c], ms[r][c]),
                    "M[{r}][{c}] {} vs {}",
                    mp[r][c],
                    ms[r][c]
                );
            }
        }
        for (fp, fs) in [
            (
                *Aba::forward_dynamics(&planar, &mut dp, &q, &v, &tp, None).unwrap(),
                *Aba::forward_dynamics(&spatial, &mut ds, &q, &v, &ts, None).unwrap(),
            ),
            (
                *Crba::forward_dynamics(&planar, &mut dp, &q, &v, &tp, None).unwrap(),
                *Crba::forward_dynamics(&spatial, &mut ds, &q, &v, &ts, None).unwrap(),
            ),
        ] {
            for k in 0..N {
                assert!((fp[k] - fs[k]).abs() < 1e-9 && (fp[k] - a[k]).abs() < 1e-9);
            }
        }
        let ep = kinetic_energy(&planar, &mut dp, &q, &v).unwrap()
            + potential_energy(&planar, &mut dp, &q).unwrap();
        let es = kinetic_energy(&spatial, &mut ds, &q, &v).unwrap()
            + potential_energy(&spatial, &mut ds, &q).unwrap();
        assert!(close(ep, es), "energy {ep} vs {es}");
    }
}

#[test]
fn planar_matches_spatial() {
    let mut rng = Rng::new(0x5EED_0003);
    for _ in 0..5 {
        check::<1>(&mut rng);
        check::<3>(&mut rng);
        check::<8>(&mut rng);
        check::<20>(&mut rng);
    }
}
