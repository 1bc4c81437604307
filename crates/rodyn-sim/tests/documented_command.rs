//! The README's command, `rodyn-sim run quadruped-trot -o out/`, as written:
//! the Aibo-size robot trots 5 s and stays upright above the ground, as the
//! README's picture shows; at the 1 ms step that used to be the default the
//! simulator reports the robot turning over instead of going on silently.

use std::process::Command;

fn run(extra: &[&str], out: &std::path::Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_rodyn-sim"))
        .args(["run", "quadruped-trot", "-o"])
        .arg(out)
        .args(extra)
        .output()
        .expect("rodyn-sim runs")
}

fn last_row(out: &std::path::Path) -> (Vec<String>, Vec<f64>) {
    let text = std::fs::read_to_string(out.join("quadruped-trot.csv")).unwrap();
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    let last = lines
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    (header, last)
}

#[test]
fn the_documented_trot_stays_upright_and_a_bad_step_is_reported() {
    let dir = std::env::temp_dir().join(format!("rodyn-sim-trot-{}", std::process::id()));
    let output = run(&[], &dir);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    // "final torso position x = … m, y = … m, z = … m"
    let line = stdout
        .lines()
        .find(|l| l.starts_with("final torso position"))
        .unwrap();
    let number = |key: &str| -> f64 {
        let rest = &line[line.find(key).unwrap() + key.len()..];
        rest.split_whitespace().next().unwrap().parse().unwrap()
    };
    let (x, z) = (number("x = "), number("z = "));
    assert!(z > 0.09, "trunk at {z} m after 5 s");
    assert!(x > 1.0, "forward only {x} m in 5 s");
    let (header, q) = last_row(&dir);
    let at = |name: &str| q[header.iter().position(|h| h == name).unwrap()];
    let up = 1.0 - 2.0 * (at("q_qx").powi(2) + at("q_qy").powi(2));
    assert!(up > 0.95, "trunk tilted: its z axis at {up} of vertical");
    assert!((at("t") - 5.0).abs() < 1e-9);

    let failing = dir.join("1ms");
    let output = run(&["--dt", "1e-3", "--duration", "2.5"], &failing);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        !output.status.success(),
        "a flipped robot must fail the run"
    );
    assert!(
        stderr.contains("the simulation failed at t = ")
            && (stderr.contains("upside down") || stderr.contains("below the ground")),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
