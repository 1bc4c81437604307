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

#[cfg(test)]
mod tests {
    use super::read;

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
