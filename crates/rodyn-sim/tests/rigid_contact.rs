//! `--integrator rigid-contact`: the quadruped dropped 3 cm lands on rigid
//! feet and stands at a 5 ms step (where the compliant feet need 0.5 ms),
//! and a scenario without feet is refused with a reason, not simulated.

use std::process::Command;

fn run(scenario: &str, out: &std::path::Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_rodyn-sim"))
        .args([
            "run",
            scenario,
            "--integrator",
            "rigid-contact",
            "--dt",
            "0.005",
        ])
        .args(["--duration", "2", "-o"])
        .arg(out)
        .output()
        .expect("rodyn-sim runs")
}

#[test]
fn rigid_feet_stand_at_5_ms_and_feetless_scenarios_are_refused() {
    let dir = std::env::temp_dir().join(format!("rodyn-sim-rigid-{}", std::process::id()));
    let output = run("quadruped-stand", &dir);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(stdout.contains("KKT f64 rigid-contact"), "{stdout}");
    // "final torso position x = … m, y = … m, z = … m": standing, 1.1 mm
    // below the 120.1 mm stance height as the legs give under the PD gains.
    let line = stdout
        .lines()
        .find(|l| l.starts_with("final torso position"))
        .unwrap();
    let z: f64 = line[line.find("z = ").unwrap() + 4..]
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((z - 0.119).abs() < 0.002, "trunk at {z} m");

    let output = run("arm-swing", &dir);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success());
    assert!(stderr.contains("no feet for rigid contact"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}
