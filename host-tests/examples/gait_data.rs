//! Writes the synthetic gait cycle that the prosthesis example analyses:
//! `host-tests/data/gait/joint_fourier.csv` and `ground_reaction.csv`.
//!
//! ```text
//! cargo run -p rodyn-host-tests --example gait_data --release
//! ```
//!
//! The data are synthetic, not measured. Joint angles follow typical
//! normative sagittal curves of level walking at a self-selected speed
//! (keyframes below, read from the published averages of Winter 1991 and
//! Perry 1992), fitted with six Fourier harmonics; the left leg repeats the
//! right half a cycle later. The pelvis is then placed so that the lowest
//! point of the feet stays on the ground without sliding (heel, then toe,
//! pivoting), and that path is fitted with ten harmonics plus a constant
//! forward speed. Ground reactions are the classic shapes: a vertical
//! double hump and an anterior-posterior braking-then-propulsion wave over
//! each foot's 60 % stance, with the centre of pressure moving from heel to
//! toe, scaled so that over one cycle the vertical impulse equals body
//! weight times the period (periodic motion needs exactly that).

#[path = "../tests/gait_support/mod.rs"]
#[allow(dead_code)]
mod gait_support;

use gait_support::data::{data_dir, FootLoad, GaitCycle, GroundReaction, GROUND_REACTION_HEADER};
use gait_support::fourier::FourierSeries;
use gait_support::gait_planar::{endpoint, ENDPOINTS_F64, MODEL_F64, NQ};
use rodyn::algorithm::kinematics::forward_kinematics;
use rodyn::planar::Planar;
use rodyn::Data;
use rodyn_cli::no_arguments;
use std::f64::consts::PI;

/// Stride period T (s): a cadence of 0.91 strides (1.8 steps) per second.
const PERIOD: f64 = 1.1;
/// Fraction of the cycle each foot is on the ground.
const STANCE: f64 = 0.6;
/// Harmonics of the joint angle fits.
const JOINT_HARMONICS: usize = 6;
/// Harmonics of the fits of the pelvis path: few, because the anchored
/// path has kinks where the pivot changes and, from these synthetic joint
/// angles, a forward lurch in double support that real walkers do not show;
/// a low-pass fit keeps the accelerations of the body near real ones at
/// the price of some foot slip (reported by the example).
const PELVIS_FORWARD_HARMONICS: usize = 2;
/// Harmonics of the fit of the pelvis height.
const PELVIS_VERTICAL_HARMONICS: usize = 4;
/// Samples per cycle for fitting.
const SAMPLES: usize = 1000;

/// Hip flexion (deg) against percent of the cycle from heel strike.
const HIP_FLEXION: &[(f64, f64)] = &[
    (0.0, 30.0),
    (10.0, 27.0),
    (20.0, 19.0),
    (30.0, 10.0),
    (40.0, 2.0),
    (50.0, -6.0),
    (55.0, -10.0),
    (60.0, -7.0),
    (65.0, 0.0),
    (70.0, 10.0),
    (75.0, 18.0),
    (80.0, 25.0),
    (85.0, 31.0),
    (90.0, 33.0),
    (95.0, 31.0),
    (100.0, 30.0),
];
/// Knee flexion (deg).
const KNEE_FLEXION: &[(f64, f64)] = &[
    (0.0, 3.0),
    (5.0, 9.0),
    (12.0, 17.0),
    (18.0, 18.0),
    (25.0, 12.0),
    (35.0, 6.0),
    (42.0, 4.0),
    (50.0, 8.0),
    (55.0, 18.0),
    (60.0, 35.0),
    (65.0, 50.0),
    (70.0, 60.0),
    (73.0, 62.0),
    (78.0, 56.0),
    (85.0, 36.0),
    (90.0, 19.0),
    (95.0, 7.0),
    (100.0, 3.0),
];
/// Ankle dorsiflexion (deg; plantarflexion negative).
const ANKLE_DORSIFLEXION: &[(f64, f64)] = &[
    (0.0, 0.0),
    (5.0, -5.0),
    (10.0, -4.0),
    (20.0, 3.0),
    (30.0, 7.0),
    (40.0, 9.0),
    (48.0, 10.0),
    (53.0, 6.0),
    (58.0, -5.0),
    (62.0, -15.0),
    (66.0, -11.0),
    (72.0, -2.0),
    (80.0, 3.0),
    (90.0, 3.0),
    (100.0, 0.0),
];
/// Mean anterior tilt of the pelvis (deg). Clinical hip angles are the
/// thigh's relative to the pelvis, which walks tilted forward by about this
/// much, so the thigh's angle to the vertical is hip flexion minus the tilt.
const MEAN_PELVIC_TILT: f64 = 10.0;
/// Anterior pelvic tilt about its mean (deg): two small waves per cycle.
const PELVIC_TILT: &[(f64, f64)] = &[
    (0.0, 0.0),
    (12.5, -1.5),
    (25.0, 0.0),
    (37.5, 1.5),
    (50.0, 0.0),
    (62.5, -1.5),
    (75.0, 0.0),
    (87.5, 1.5),
    (100.0, 0.0),
];
/// Forward lean of the upper body in the world (deg), about a 3° mean.
const TRUNK_LEAN: &[(f64, f64)] = &[
    (0.0, 3.0),
    (12.5, 4.0),
    (25.0, 3.0),
    (37.5, 2.0),
    (50.0, 3.0),
    (62.5, 4.0),
    (75.0, 3.0),
    (87.5, 2.0),
    (100.0, 3.0),
];

/// Peaks of the vertical ground reaction shape `a sin(πs) + b sin(3πs)` (in
/// body weights, before the impulse scaling) at s = 1/4 and 3/4 of stance,
/// and its midstance valley.
const VERTICAL_PEAK: f64 = 1.15;
const VERTICAL_VALLEY: f64 = 0.75;
/// Peak braking and propulsive force (body weights).
const SHEAR_PEAK: f64 = 0.2;

/// Piecewise-linear interpolation of keyframes at `percent`.
fn keyframe(curve: &[(f64, f64)], percent: f64) -> f64 {
    let p = percent.rem_euclid(100.0);
    let k = curve
        .windows(2)
        .position(|w| p <= w[1].0)
        .unwrap_or(curve.len() - 2);
    let ((p0, y0), (p1, y1)) = (curve[k], curve[k + 1]);
    y0 + (y1 - y0) * (p - p0) / (p1 - p0)
}

/// `SAMPLES` samples of `f(percent)` over one cycle.
fn sampled(f: impl Fn(f64) -> f64) -> Vec<f64> {
    (0..SAMPLES)
        .map(|j| f(100.0 * j as f64 / SAMPLES as f64))
        .collect()
}

/// The joint-angle series in model coordinates (rad); the pelvis position
/// series are placeholders until [`place_pelvis`].
fn joint_series() -> Vec<FourierSeries> {
    let fit = |f: &dyn Fn(f64) -> f64| {
        FourierSeries::fit(
            &sampled(|p| f(p).to_radians()),
            PERIOD,
            0.0,
            JOINT_HARMONICS,
        )
    };
    let zero = FourierSeries::fit(&[0.0; 3], PERIOD, 0.0, 1);
    // Model angles turn counter-clockwise about z (x forward, y up): an
    // anterior tilt or forward lean is negative, knee flexion is negative.
    let pitch = |p: f64| -MEAN_PELVIC_TILT - keyframe(PELVIC_TILT, p);
    vec![
        zero.clone(),
        zero,
        fit(&pitch),
        fit(&|p| -keyframe(TRUNK_LEAN, p) - pitch(p)),
        fit(&|p| keyframe(HIP_FLEXION, p + 50.0)),
        fit(&|p| -keyframe(KNEE_FLEXION, p + 50.0)),
        fit(&|p| keyframe(ANKLE_DORSIFLEXION, p + 50.0)),
        fit(&|p| keyframe(HIP_FLEXION, p)),
        fit(&|p| -keyframe(KNEE_FLEXION, p)),
        fit(&|p| keyframe(ANKLE_DORSIFLEXION, p)),
    ]
}

/// Fits the pelvis path that keeps the lowest heel or toe on the ground
/// (y = 0) and not sliding: the pelvis moves opposite to that point's motion
/// relative to it. Returns the forward speed (m/s).
fn place_pelvis(coordinates: &mut [FourierSeries]) -> f64 {
    let model = MODEL_F64;
    let mut data = Box::new(Data::<f64, 8, 10, Planar>::new());
    let feet = [
        endpoint::L_HEEL,
        endpoint::L_TOE,
        endpoint::R_HEEL,
        endpoint::R_TOE,
    ];
    // Each foot point relative to the pelvis at zero pelvis x and y.
    let relative: Vec<[[f64; 2]; 4]> = (0..=SAMPLES)
        .map(|j| {
            let t = PERIOD * j as f64 / SAMPLES as f64;
            let mut q = [0.0; NQ];
            for k in 2..NQ {
                q[k] = coordinates[k].evaluate(t)[0];
            }
            forward_kinematics(&model, &mut data, &q).expect("finite joint angles");
            feet.map(|e| {
                let p = ENDPOINTS_F64[e].world_position(&data.o_m_i).unwrap();
                [p.x, p.y]
            })
        })
        .collect();
    // Points of the feet on the ground: the right foot in stance over the
    // first 60 % of the cycle, the left from 50 % on.
    let in_stance = |j: usize, point: usize| {
        let percent = 100.0 * j as f64 / SAMPLES as f64;
        let since_strike = if point < 2 {
            (percent - 50.0).rem_euclid(100.0)
        } else {
            percent
        };
        since_strike <= 100.0 * STANCE
    };
    let lowest = |j: usize| {
        (0..4)
            .filter(|&k| in_stance(j, k))
            .min_by(|&a, &b| relative[j][a][1].total_cmp(&relative[j][b][1]))
            .expect("a foot is always in stance")
    };
    let mut x = vec![0.0; SAMPLES + 1];
    let mut y = vec![0.0; SAMPLES + 1];
    let mut previous_anchor = usize::MAX;
    let mut clearance = (f64::INFINITY, 0.0);
    let mut hover = (0.0_f64, 0.0);
    for j in 0..=SAMPLES {
        let anchor = lowest(j);
        y[j] = -relative[j][anchor][1];
        if j > 0 {
            let pivot = lowest(j - 1);
            x[j] = x[j - 1] - (relative[j][pivot][0] - relative[j - 1][pivot][0]);
        }
        if anchor != previous_anchor {
            let name = ["left heel", "left toe", "right heel", "right toe"][anchor];
            rodyn_cli::outln!(
                "{:5.1} % of the cycle: {name} takes the weight",
                100.0 * j as f64 / SAMPLES as f64
            );
            previous_anchor = anchor;
        }
        let percent = 100.0 * j as f64 / SAMPLES as f64;
        for foot in [[0, 1], [2, 3]] {
            let height = foot.map(|k| relative[j][k][1] + y[j]);
            let height = height[0].min(height[1]);
            if in_stance(j, foot[0]) && height > hover.0 {
                hover = (height, percent);
            } else if !in_stance(j, foot[0]) && height < clearance.0 {
                clearance = (height, percent);
            }
        }
    }
    rodyn_cli::outln!(
        "swing foot: lowest {:.1} mm above the ground (at {:.1} %); stance foot: up to {:.1} mm above it (at {:.1} %)",
        1e3 * clearance.0, clearance.1, 1e3 * hover.0, hover.1
    );
    let speed = x[SAMPLES] / PERIOD;
    coordinates[0] = FourierSeries::fit(&x[..SAMPLES], PERIOD, speed, PELVIS_FORWARD_HARMONICS);
    coordinates[1] = FourierSeries::fit(&y[..SAMPLES], PERIOD, 0.0, PELVIS_VERTICAL_HARMONICS);
    speed
}

/// Ground reaction of one foot at `s`, the fraction of its stance (0 at heel
/// strike, 1 at toe off), in body weights; `None` in swing.
fn foot_shape(s: f64) -> Option<([f64; 2], f64)> {
    if !(0.0..=1.0).contains(&s) {
        return None;
    }
    // a sin(π/4) + b sin(3π/4) = peak and a − b = valley.
    let b = (VERTICAL_PEAK / (PI / 4.0).sin() - VERTICAL_VALLEY) / 2.0;
    let a = VERTICAL_VALLEY + b;
    let vertical = a * (PI * s).sin() + b * (3.0 * PI * s).sin();
    let anterior = -SHEAR_PEAK * (2.0 * PI * s).sin();
    let heel = ENDPOINTS_F64[endpoint::R_HEEL].position.x;
    let toe = ENDPOINTS_F64[endpoint::R_TOE].position.x;
    Some(([anterior, vertical], heel + (toe - heel) * s))
}

/// The mean of the vertical shape over one stance, analytically:
/// `2a/π + 2b/(3π)`, for the impulse scaling.
fn vertical_shape_mean() -> f64 {
    let n = 100_000;
    (0..n)
        .map(|j| foot_shape((j as f64 + 0.5) / n as f64).map_or(0.0, |(f, _)| f[1]))
        .sum::<f64>()
        / n as f64
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    no_arguments("gait_data", "writes host-tests/data/gait")?;
    let mut coordinates = joint_series();
    let speed = place_pelvis(&mut coordinates);
    let cycle = GaitCycle { coordinates };
    let weight = MODEL_F64.total_mass() * 9.81;
    // Both feet together carry body weight on average over the cycle.
    let scale = weight / (2.0 * STANCE * vertical_shape_mean());
    let load = |percent: f64| {
        let s = percent / 100.0 / STANCE;
        foot_shape(s).map_or(FootLoad::default(), |(f, cop)| FootLoad {
            force: [scale * f[0], scale * f[1]],
            cop,
        })
    };
    let mut grf = String::from(GROUND_REACTION_HEADER);
    grf.push('\n');
    for percent in 0..=100 {
        let p = f64::from(percent);
        let row = GroundReaction {
            percent: p,
            time: PERIOD * p / 100.0,
            right: load(p),
            left: load((p - 50.0).rem_euclid(100.0)),
        };
        grf.push_str(&row.to_csv_line());
        grf.push('\n');
    }
    let dir = data_dir();
    std::fs::create_dir_all(&dir)?;
    std::fs::write(dir.join("joint_fourier.csv"), cycle.to_csv())?;
    std::fs::write(dir.join("ground_reaction.csv"), grf)?;
    rodyn_cli::outln!(
        "speed {speed:.3} m/s, stride {:.3} m, vertical peak {:.3} BW; wrote {}",
        speed * PERIOD,
        scale * VERTICAL_PEAK / weight,
        dir.display()
    );
    Ok(())
}
