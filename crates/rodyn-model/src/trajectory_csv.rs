//! `rodyn-model view --trajectory FILE`: a logged trajectory as CSV, one
//! sample a line, `t` (s) then the model's `nq` coordinates, under one
//! header line (such as `t,q0,q1,…`), read for the viewer to replay.

/// The times (s) and configurations of the CSV text `text` of `file`, for
/// a model of `nq` coordinates. An error names the file, the line and what
/// is wrong: a field that is not a finite number, a line of the wrong
/// length, a time that does not increase.
pub fn read(text: &str, file: &str, nq: usize) -> Result<(Vec<f64>, Vec<Vec<f64>>), String> {
    let mut times = Vec::new();
    let mut configurations = Vec::new();
    for (k, line) in text.lines().enumerate().skip(1) {
        if line.trim().is_empty() {
            continue;
        }
        let at = format!("{file}:{}", k + 1);
        let fields: Vec<f64> = line
            .split(',')
            .map(|field| {
                let x = field.trim();
                x.parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| format!("{at}: `{x}` is not a finite number"))
            })
            .collect::<Result<_, _>>()?;
        if fields.len() != nq + 1 {
            return Err(format!(
                "{at}: {} fields, but t and nq = {nq} coordinates make {}",
                fields.len(),
                nq + 1
            ));
        }
        let t = fields[0];
        if times.last().is_some_and(|&last| t <= last) {
            return Err(format!("{at}: t = {t} s does not follow the line before"));
        }
        times.push(t);
        configurations.push(fields[1..].to_vec());
    }
    if times.len() < 2 {
        return Err(format!(
            "{file}: {} samples; a trajectory needs two at least",
            times.len()
        ));
    }
    Ok((times, configurations))
}

/// Largest distance of a logged quaternion's norm from 1 that is taken
/// for rounding: an `f32` run printed in its shortest decimals is off by
/// about 1e-7, far above `f64`'s tolerance of 1e3 ε.
const LOGGED_NORM_TOLERANCE: f64 = 1e-5;

/// Scales the unit quaternion starting at each of `starts` (offsets into
/// every configuration of `configurations`, `[qx qy qz qw]`) back to norm 1
/// when it is off by rounding only; a quaternion further off is left for
/// the kinematics to refuse, naming the joint.
pub fn normalise_quaternions(configurations: &mut [Vec<f64>], starts: &[usize]) {
    for q in configurations {
        for &k in starts {
            let Some(quaternion) = q.get_mut(k..k + 4) else {
                continue;
            };
            let norm = quaternion.iter().map(|x| x * x).sum::<f64>().sqrt();
            if (norm - 1.0).abs() <= LOGGED_NORM_TOLERANCE {
                quaternion.iter_mut().for_each(|x| *x /= norm);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{normalise_quaternions, read};

    #[test]
    fn rounded_quaternions_are_normalised_and_wrong_ones_kept() {
        let mut q = vec![
            vec![0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 1.000_000_01],
            vec![0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 1.1],
        ];
        normalise_quaternions(&mut q, &[3]);
        assert_eq!(q[0][6], 1.0);
        assert_eq!(q[0][2], 0.1);
        assert_eq!(q[1][6], 1.1);
    }

    #[test]
    fn samples_read_and_bad_lines_are_named() {
        let (t, q) = read("t,q0,q1\n0,1,2\n0.02,1.5,-2.5\n", "run.csv", 2).expect("reads");
        assert_eq!(t, vec![0.0, 0.02]);
        assert_eq!(q, vec![vec![1.0, 2.0], vec![1.5, -2.5]]);
        let short = read("t,q0,q1\n0,1\n0.1,1,2\n", "run.csv", 2).unwrap_err();
        assert_eq!(
            short,
            "run.csv:2: 2 fields, but t and nq = 2 coordinates make 3"
        );
        let nan = read("t,q0\n0,1\n0.1,NaN\n", "run.csv", 1).unwrap_err();
        assert_eq!(nan, "run.csv:3: `NaN` is not a finite number");
        let back = read("t,q0\n0.1,1\n0.1,2\n", "run.csv", 1).unwrap_err();
        assert_eq!(back, "run.csv:3: t = 0.1 s does not follow the line before");
        assert!(read("t,q0\n0,1\n", "run.csv", 1).is_err());
    }
}
