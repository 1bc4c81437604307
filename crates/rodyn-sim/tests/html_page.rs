//! `rodyn-sim run --html`: the page holds the run's poses (rodyn's forward
//! kinematics of the recorded q) and its foot contacts.

use std::process::Command;

#[test]
fn the_page_holds_the_runs_poses_and_contacts() {
    let dir = std::env::temp_dir().join(format!("rodyn-sim-html-{}", std::process::id()));
    let page = dir.join("stand.html");
    let output = Command::new(env!("CARGO_BIN_EXE_rodyn-sim"))
        .args(["run", "quadruped-stand", "--duration", "1", "-o"])
        .arg(&dir)
        .arg("--html")
        .arg(&page)
        .output()
        .expect("rodyn-sim runs");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let html = std::fs::read_to_string(&page).unwrap();
    let start = html.find("type=\"application/json\">").unwrap() + 24;
    let end = start + html[start..].find("</script>").unwrap();
    let scene: serde_json::Value = serde_json::from_str(&html[start..end]).unwrap();
    let trajectory = &scene["trajectory"];
    // Samples every 10 ms from 0 to 1 s.
    let t = trajectory["t"].as_array().unwrap();
    assert_eq!(t.len(), 101);
    assert!((t[100].as_f64().unwrap() - 1.0).abs() < 1e-9);
    // The trunk's height in the last sample is the one the run prints
    // (to its 0.1 mm), both from the recorded q.
    let line = stdout
        .lines()
        .find(|l| l.starts_with("final torso position"))
        .unwrap();
    let printed: f64 = line[line.find("z = ").unwrap() + 4..]
        .trim_end_matches(" m")
        .parse()
        .unwrap();
    let nb = scene["bodies"].as_array().unwrap().len();
    let last = trajectory["poses"][100].as_array().unwrap();
    assert_eq!(last.len(), 12 * nb);
    let z = last[11].as_f64().unwrap();
    assert!((z - printed).abs() <= 0.5e-4, "{z} against {printed}");
    // Standing still on four feet: the ground carries the weight, 1.6 kg
    // times 9.81 m/s², within 2 %.
    let contacts = trajectory["contacts"][100].as_array().unwrap();
    assert_eq!(contacts.len(), 4 * 6, "four feet, each a point and a force");
    let lift: f64 = contacts.chunks(6).map(|c| c[5].as_f64().unwrap()).sum();
    assert!((lift / (1.6 * 9.81) - 1.0).abs() < 0.02, "{lift} N");
    std::fs::remove_dir_all(dir).unwrap();
}
