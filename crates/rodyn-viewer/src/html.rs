//! The page: a template with the style, three.js, the scene's JSON and the
//! page's script written into it.

use crate::ellipsoid::inertia_ellipsoid;
use crate::scene::{round_micro, Geometry, Joint, Scene};
use base64::Engine as _;
use flate2::write::GzEncoder;
use flate2::Compression;
use serde_json::{json, Value};
use std::io::Write as _;
use std::sync::OnceLock;

const TEMPLATE: &str = include_str!("../page/viewer.html");
const STYLE: &str = include_str!("../page/viewer.css");
const SCRIPT: &str = include_str!("../page/viewer.js");
const THREE: &str = include_str!("../vendor/three/three.min.js");

/// What makes a scene impossible to draw.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HtmlError(pub String);

impl std::fmt::Display for HtmlError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for HtmlError {}

/// The self-contained HTML page of `scene`.
///
/// # Errors
/// A body whose parent does not come before it, a visual or endpoint on a
/// body or mesh that does not exist, a trajectory whose samples do not give
/// one pose per body or whose times decrease, a number that is not finite,
/// joint limits whose lower bound is not below the upper, a mimic joint
/// that is not a one-coordinate joint following another, or a starting
/// configuration of the wrong length.
pub fn write_html(scene: &Scene) -> Result<String, HtmlError> {
    check(scene)?;
    let data = page_data(scene)?;
    let three = compressed_three()?;
    // `<` only occurs inside JSON strings, where \u003c means the same; so
    // no name can close the <script> element that holds the JSON.
    let json = serde_json::to_string(&data)
        .map_err(|e| HtmlError(format!("cannot write the scene as JSON: {e}")))?
        .replace('<', "\\u003c");
    Ok(fill(
        TEMPLATE,
        &[
            (
                "{{TITLE}}",
                &escape_text(&format!("{} — rodyn viewer", scene.name)),
            ),
            ("{{STYLE}}", STYLE),
            ("{{SCENE}}", &json),
            ("{{THREE}}", three),
            ("{{SCRIPT}}", SCRIPT),
        ],
    ))
}

/// `bytes` gzip-compressed, as base64 text, which the page inflates with
/// the browser's `DecompressionStream`: meshes (COLLADA's XML above all)
/// and three.js shrink to a fraction of their size.
fn gzip_base64(bytes: &[u8]) -> Result<String, HtmlError> {
    let mut gzip = GzEncoder::new(Vec::with_capacity(bytes.len() / 4), Compression::default());
    let compressed = gzip
        .write_all(bytes)
        .and_then(|()| gzip.finish())
        .map_err(|e| HtmlError(format!("cannot compress a block of the page: {e}")))?;
    Ok(base64::engine::general_purpose::STANDARD.encode(compressed))
}

/// three.js, compressed once per process.
fn compressed_three() -> Result<&'static str, HtmlError> {
    static COMPRESSED: OnceLock<String> = OnceLock::new();
    if let Some(done) = COMPRESSED.get() {
        return Ok(done);
    }
    let compressed = gzip_base64(THREE.as_bytes())?;
    Ok(COMPRESSED.get_or_init(|| compressed))
}

/// `template` with each key replaced by its value, once, in one pass (so
/// nothing inserted is read again as a key).
fn fill(template: &str, parts: &[(&str, &str)]) -> String {
    let mut out =
        String::with_capacity(template.len() + parts.iter().map(|p| p.1.len()).sum::<usize>());
    let mut rest = template;
    while let Some((at, key, value)) = parts
        .iter()
        .filter_map(|(k, v)| rest.find(k).map(|at| (at, *k, *v)))
        .min_by_key(|p| p.0)
    {
        out.push_str(&rest[..at]);
        out.push_str(value);
        rest = &rest[at + key.len()..];
    }
    out.push_str(rest);
    out
}

fn escape_text(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn check(scene: &Scene) -> Result<(), HtmlError> {
    let nb = scene.bodies.len();
    let err = |m: String| Err(HtmlError(m));
    for (i, b) in scene.bodies.iter().enumerate() {
        if b.parent.is_some_and(|p| p >= i) {
            return err(format!(
                "body `{}` (number {i}) has parent {:?}, which does not come before it",
                b.name, b.parent
            ));
        }
        let numbers = b
            .placement
            .rot
            .iter()
            .flatten()
            .chain(&b.placement.trans)
            .chain(&b.com)
            .chain(b.inertia.iter().flatten())
            .chain([&b.mass]);
        if numbers.clone().any(|v| !v.is_finite()) {
            return err(format!(
                "body `{}` has a placement, mass or inertia that is not finite",
                b.name
            ));
        }
        if let Some([lower, upper]) = b.limits {
            if b.joint.nq() != 1 || !lower.is_finite() || !upper.is_finite() || lower >= upper {
                return err(format!(
                    "joint `{}` has limits [{lower}, {upper}]: limits need a revolute or prismatic joint and finite bounds, the lower below the upper",
                    b.joint_name
                ));
            }
        }
    }
    for (k, m) in scene.mimics.iter().enumerate() {
        let one_coordinate = |i: usize| scene.bodies.get(i).is_some_and(|b| b.joint.nq() == 1);
        if m.follower == m.leader || !one_coordinate(m.follower) || !one_coordinate(m.leader) {
            return err(format!(
                "mimic {k} makes body {} follow body {} (of {nb}): both must be revolute or prismatic joints, and differ",
                m.follower, m.leader
            ));
        }
        if !m.multiplier.is_finite() || !m.offset.is_finite() {
            return err(format!(
                "mimic {k} (body {} following body {}) has a multiplier or offset that is not finite",
                m.follower, m.leader
            ));
        }
        if scene.mimics[..k]
            .iter()
            .any(|earlier| earlier.follower == m.follower)
        {
            return err(format!(
                "body {} follows two joints (mimic {k})",
                m.follower
            ));
        }
    }
    for v in &scene.visuals {
        if v.body.is_some_and(|b| b >= nb) {
            return err(format!("a visual is on body {:?} of {nb}", v.body));
        }
        if let Geometry::Mesh { mesh, .. } = v.geometry {
            if mesh >= scene.meshes.len() {
                return err(format!(
                    "a visual uses mesh {mesh} of {}",
                    scene.meshes.len()
                ));
            }
        }
    }
    for e in &scene.endpoints {
        if e.body.is_some_and(|b| b >= nb) {
            return err(format!(
                "endpoint `{}` is on body {:?} of {nb}",
                e.name, e.body
            ));
        }
    }
    if !scene.q.is_empty() && scene.q.len() != scene.nq() {
        return err(format!(
            "the starting configuration has {} numbers but the model has nq = {}",
            scene.q.len(),
            scene.nq()
        ));
    }
    if let Some(t) = &scene.trajectory {
        if t.t.is_empty() || t.poses.len() != t.t.len() {
            return err(format!(
                "the trajectory has {} times and {} samples of poses (it needs one or more of each, as many of one as of the other)",
                t.t.len(),
                t.poses.len()
            ));
        }
        if !t.contacts.is_empty() && t.contacts.len() != t.t.len() {
            return err(format!(
                "the trajectory has {} times and {} samples of contacts",
                t.t.len(),
                t.contacts.len()
            ));
        }
        for (k, (time, poses)) in t.t.iter().zip(&t.poses).enumerate() {
            if poses.len() != nb {
                return err(format!(
                    "sample {k} (t = {time} s) has {} poses for {nb} bodies",
                    poses.len()
                ));
            }
            if !time.is_finite() || (k > 0 && *time < t.t[k - 1]) {
                return err(format!(
                    "sample {k}'s time {time} s is not finite or comes before the previous sample's"
                ));
            }
            let finite = poses.iter().all(|p| {
                p.rot
                    .iter()
                    .flatten()
                    .chain(&p.trans)
                    .all(|v| v.is_finite())
            });
            let contacts_finite = t.contacts.get(k).is_none_or(|c| {
                c.iter()
                    .all(|c| c.position.iter().chain(&c.force).all(|v| v.is_finite()))
            });
            if !finite || !contacts_finite {
                return err(format!(
                    "sample {k} (t = {time} s) has a pose or contact that is not finite"
                ));
            }
        }
    }
    Ok(())
}

fn page_data(scene: &Scene) -> Result<Value, HtmlError> {
    let bodies: Vec<Value> = scene
        .bodies
        .iter()
        .map(|b| {
            let joint = match b.joint {
                Joint::Revolute { axis } => json!({"type": "revolute", "axis": axis}),
                Joint::Prismatic { axis } => json!({"type": "prismatic", "axis": axis}),
                Joint::FreeFlyer => json!({"type": "free-flyer"}),
                Joint::PlanarFloating => json!({"type": "planar-floating"}),
            };
            let ellipsoid = inertia_ellipsoid(b.mass, &b.inertia).map(|e| {
                json!({
                    "radii": e.radii.map(round_micro),
                    "axes": e.axes.iter().flatten().map(|v| round_micro(*v)).collect::<Vec<_>>(),
                })
            });
            json!({
                "name": b.name,
                "joint_name": b.joint_name,
                "parent": b.parent,
                "joint": joint,
                "nq": b.joint.nq(),
                "placement": b.placement.to_page(),
                "mass": b.mass,
                "com": b.com.map(round_micro),
                "ellipsoid": ellipsoid,
                "limits": b.limits,
            })
        })
        .collect();
    let visuals: Vec<Value> = scene
        .visuals
        .iter()
        .map(|v| {
            let geometry = match &v.geometry {
                Geometry::Box { size } => json!({"type": "box", "size": size}),
                Geometry::Cylinder { radius, length } => {
                    json!({"type": "cylinder", "radius": radius, "length": length})
                }
                Geometry::Sphere { radius } => json!({"type": "sphere", "radius": radius}),
                Geometry::Mesh { mesh, scale } => {
                    json!({"type": "mesh", "mesh": mesh, "scale": scale})
                }
            };
            json!({"body": v.body, "pose": v.pose.to_page(), "geometry": geometry, "color": v.color})
        })
        .collect();
    let meshes: Vec<Value> = scene
        .meshes
        .iter()
        .map(|m| {
            Ok(json!({
                "name": m.name,
                "format": m.format.name(),
                "gzip": gzip_base64(&m.bytes)?,
            }))
        })
        .collect::<Result<_, HtmlError>>()?;
    let endpoints: Vec<Value> = scene
        .endpoints
        .iter()
        .map(|e| json!({"name": e.name, "body": e.body, "position": e.position}))
        .collect();
    let mut q = scene.q.clone();
    if q.is_empty() {
        for b in &scene.bodies {
            match b.joint {
                Joint::FreeFlyer => q.extend([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]),
                j => q.extend(std::iter::repeat_n(0.0, j.nq())),
            }
        }
    }
    let trajectory = scene.trajectory.as_ref().map(|t| {
        let poses: Vec<Vec<f64>> = t
            .poses
            .iter()
            .map(|sample| sample.iter().flat_map(|p| p.to_page()).collect())
            .collect();
        let contacts: Vec<Vec<f64>> = t
            .contacts
            .iter()
            .map(|sample| {
                sample
                    .iter()
                    .flat_map(|c| c.position.iter().chain(&c.force).map(|v| round_micro(*v)))
                    .collect()
            })
            .collect();
        json!({"t": t.t, "poses": poses, "contacts": contacts})
    });
    let mimics: Vec<Value> = scene
        .mimics
        .iter()
        .map(|m| {
            json!({
                "follower": m.follower,
                "leader": m.leader,
                "multiplier": m.multiplier,
                "offset": m.offset,
            })
        })
        .collect();
    Ok(json!({
        "name": scene.name,
        "up": scene.up,
        "nq": scene.nq(),
        "q": q,
        "bodies": bodies,
        "mimics": mimics,
        "visuals": visuals,
        "meshes": meshes,
        "endpoints": endpoints,
        "trajectory": trajectory,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Body, Pose, Trajectory};

    fn pendulum() -> Scene {
        let mut scene = Scene::new("pendulum </script>");
        scene.bodies.push(Body {
            name: "rod".into(),
            joint_name: "hinge".into(),
            parent: None,
            joint: Joint::Revolute {
                axis: [0.0, 1.0, 0.0],
            },
            placement: Pose::IDENTITY,
            mass: 1.0,
            com: [0.0, 0.0, -0.5],
            inertia: [[0.08, 0.0, 0.0], [0.0, 0.08, 0.0], [0.0, 0.0, 1e-3]],
            limits: None,
        });
        scene
    }

    /// A pendulum hanging from the first one.
    fn double_pendulum() -> Scene {
        let mut scene = pendulum();
        let mut lower = scene.bodies[0].clone();
        lower.name = "lower rod".into();
        lower.joint_name = "knee".into();
        lower.parent = Some(0);
        lower.placement.trans = [0.0, 0.0, -1.0];
        scene.bodies.push(lower);
        scene
    }

    /// The page's JSON block, parsed.
    fn page_json(html: &str) -> Value {
        let start = html.find("type=\"application/json\">").unwrap() + 24;
        let end = start + html[start..].find("</script>").unwrap();
        serde_json::from_str(&html[start..end]).unwrap()
    }

    /// The bytes of a gzip-compressed base64 block.
    fn inflate(text: &str) -> Vec<u8> {
        use std::io::Read as _;
        let gzip = base64::engine::general_purpose::STANDARD
            .decode(text)
            .unwrap();
        let mut out = Vec::new();
        flate2::read::GzDecoder::new(&gzip[..])
            .read_to_end(&mut out)
            .unwrap();
        out
    }

    #[test]
    fn the_scripts_cannot_close_their_elements() {
        assert!(!SCRIPT.contains("</script"));
        let three = compressed_three().unwrap();
        assert!(three
            .bytes()
            .all(|c| c.is_ascii_alphanumeric() || b"+/=".contains(&c)));
    }

    #[test]
    fn three_and_meshes_inflate_to_their_bytes() {
        let mut scene = pendulum();
        let stl = b"solid part\nendsolid part\n".repeat(50);
        scene.meshes.push(crate::scene::Mesh {
            name: "part.stl".into(),
            format: crate::scene::MeshFormat::Stl,
            bytes: stl.clone(),
        });
        let html = write_html(&scene).unwrap();
        let data = page_json(&html);
        let packed = data["meshes"][0]["gzip"].as_str().unwrap();
        assert_eq!(inflate(packed), stl);
        assert!(
            packed.len() < stl.len() / 4,
            "{} base64 bytes for {}",
            packed.len(),
            stl.len()
        );
        assert_eq!(inflate(compressed_three().unwrap()), THREE.as_bytes());
        assert!(
            html.len() < THREE.len() / 2,
            "the page holds three.js compressed"
        );
    }

    #[test]
    fn limits_and_mimics_reach_the_page() {
        let mut scene = double_pendulum();
        scene.bodies[1].limits = Some([-0.5, 2.0]);
        scene.mimics.push(crate::scene::Mimic {
            follower: 1,
            leader: 0,
            multiplier: -2.0,
            offset: 0.1,
        });
        let data = page_json(&write_html(&scene).unwrap());
        assert_eq!(data["bodies"][0]["limits"], Value::Null);
        assert_eq!(data["bodies"][1]["limits"], json!([-0.5, 2.0]));
        assert_eq!(
            data["mimics"],
            json!([{"follower": 1, "leader": 0, "multiplier": -2.0, "offset": 0.1}])
        );
    }

    #[test]
    fn bad_limits_and_mimics_are_refused_with_the_joint() {
        let mut scene = double_pendulum();
        scene.bodies[1].limits = Some([1.0, -1.0]);
        let e = write_html(&scene).unwrap_err();
        assert!(e.0.contains("joint `knee` has limits [1, -1]"), "{e}");
        let mut scene = double_pendulum();
        scene.bodies[0].joint = Joint::FreeFlyer;
        scene.mimics.push(crate::scene::Mimic {
            follower: 1,
            leader: 0,
            multiplier: 1.0,
            offset: 0.0,
        });
        let e = write_html(&scene).unwrap_err();
        assert!(e.0.contains("mimic 0 makes body 1 follow body 0"), "{e}");
        let mut scene = double_pendulum();
        scene.mimics.push(crate::scene::Mimic {
            follower: 1,
            leader: 0,
            multiplier: f64::NAN,
            offset: 0.0,
        });
        assert!(write_html(&scene).unwrap_err().0.contains("not finite"));
    }

    #[test]
    fn a_name_cannot_close_the_json_element() {
        let html = write_html(&pendulum()).unwrap();
        assert_eq!(
            html.matches("</script>").count(),
            3,
            "three scripts, no more"
        );
        assert!(html.contains("pendulum \\u003c/script>"));
        assert!(html.contains("<title>pendulum &lt;/script&gt; — rodyn viewer</title>"));
    }

    #[test]
    fn the_json_reads_back_with_the_poses() {
        let mut scene = pendulum();
        let mut turned = Pose::IDENTITY;
        turned.trans = [0.1, 0.2, 0.300_000_000_4];
        scene.trajectory = Some(Trajectory {
            t: vec![0.0, 0.5],
            poses: vec![vec![Pose::IDENTITY], vec![turned]],
            contacts: vec![],
        });
        let data = page_json(&write_html(&scene).unwrap());
        assert_eq!(data["nq"], 1);
        assert_eq!(data["q"], json!([0.0]));
        let second = &data["trajectory"]["poses"][1];
        assert_eq!(second.as_array().unwrap().len(), 12);
        assert_eq!(second[9], 0.1);
        assert_eq!(second[11], 0.3, "rounded to a micrometre");
        // The rod's ellipsoid from I = diag(0.08, 0.08, 0.001), m = 1:
        // a² = 5 (I_y + I_z − I_x) / 2m, and so on.
        let radii = &data["bodies"][0]["ellipsoid"]["radii"];
        let a = (2.5f64 * (0.08 + 0.001 - 0.08)).sqrt();
        let c = (2.5f64 * (0.16 - 0.001)).sqrt();
        assert!((radii[0].as_f64().unwrap() - a).abs() < 1e-6, "{radii}");
        assert!((radii[2].as_f64().unwrap() - c).abs() < 1e-6, "{radii}");
    }

    #[test]
    fn broken_scenes_are_refused_with_the_reason() {
        let mut scene = pendulum();
        scene.bodies[0].parent = Some(0);
        let e = write_html(&scene).unwrap_err();
        assert!(e.0.contains("body `rod`"), "{e}");
        let mut scene = pendulum();
        scene.trajectory = Some(Trajectory {
            t: vec![0.0],
            poses: vec![vec![]],
            contacts: vec![],
        });
        let e = write_html(&scene).unwrap_err();
        assert!(
            e.0.contains("sample 0 (t = 0 s) has 0 poses for 1 bodies"),
            "{e}"
        );
        let mut scene = pendulum();
        scene.q = vec![0.0, 1.0];
        assert!(write_html(&scene).unwrap_err().0.contains("nq = 1"));
    }
}
