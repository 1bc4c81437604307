//! `rodyn-model view`'s data: a URDF's visual geometry on the right bodies
//! at the right poses, mesh files found and read once, and a trajectory's
//! poses from rodyn's forward kinematics.

use rodyn_model::joint_limits::read_joint_limits;
use rodyn_model::runtime::RuntimeModel;
use rodyn_model::{load, view, visual::read_visuals, LoadOptions};
use rodyn_viewer::{Geometry, Joint};
use std::path::PathBuf;

const URDF: &str = r#"<?xml version="1.0"?>
<robot name="arm">
  <material name="orange"><color rgba="1 0.5 0 1"/></material>
  <link name="base">
    <visual><geometry><cylinder radius="0.05" length="0.1"/></geometry></visual>
  </link>
  <link name="upper">
    <inertial><mass value="1"/><origin xyz="0 0 0.25"/>
      <inertia ixx="0.02" iyy="0.02" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><origin xyz="0 0 0.25"/><geometry><box size="0.1 0.1 0.5"/></geometry>
      <material name="orange"/></visual>
  </link>
  <link name="tool">
    <visual><origin xyz="0.1 0 0" rpy="0 0 1.5707963267948966"/>
      <geometry><mesh filename="package://armpkg/meshes/part.stl" scale="0.001 0.001 0.001"/></geometry></visual>
    <visual><geometry><mesh filename="meshes/part.stl"/></geometry></visual>
    <visual><geometry><mesh filename="package://armpkg/meshes/missing.stl"/></geometry></visual>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><origin xyz="0 0 0.1"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="10" velocity="1"/>
  </joint>
  <joint name="tool_mount" type="fixed">
    <parent link="upper"/><child link="tool"/><origin xyz="0 0 0.5"/>
  </joint>
</robot>
"#;

/// A package folder `armpkg` (holding the URDF's meshes) and the URDF in it.
fn package(test: &str) -> (PathBuf, PathBuf) {
    let share =
        std::env::temp_dir().join(format!("rodyn-model-view-{test}-{}", std::process::id()));
    let pkg = share.join("armpkg");
    std::fs::create_dir_all(pkg.join("meshes")).unwrap();
    std::fs::create_dir_all(pkg.join("urdf")).unwrap();
    std::fs::write(pkg.join("meshes/part.stl"), b"solid part\nendsolid part\n").unwrap();
    // Relative paths are read from the URDF's folder.
    std::fs::create_dir_all(pkg.join("urdf/meshes")).unwrap();
    std::fs::copy(
        pkg.join("meshes/part.stl"),
        pkg.join("urdf/meshes/part.stl"),
    )
    .unwrap();
    let urdf = pkg.join("urdf/arm.urdf");
    std::fs::write(&urdf, URDF).unwrap();
    (share, urdf)
}

#[test]
fn visuals_sit_on_their_bodies_and_meshes_are_read_once_per_file() {
    let (share, urdf) = package("visuals");
    let model = load(&urdf, LoadOptions::default()).unwrap();
    let visuals = read_visuals(&model, std::slice::from_ref(&share)).unwrap();
    // The base's cylinder on the world, the upper link's box, the tool's
    // two meshes found (the missing one left out with a warning).
    assert_eq!(visuals.visuals.len(), 4);
    let base = &visuals.visuals[0];
    assert_eq!(base.body, None);
    assert!(
        matches!(base.geometry, Geometry::Cylinder { radius, length } if radius == 0.05 && length == 0.1)
    );
    let upper = &visuals.visuals[1];
    assert_eq!(upper.body, Some(0));
    assert_eq!(upper.pose.trans, [0.0, 0.0, 0.25]);
    assert_eq!(
        upper.color,
        Some([1.0, 0.5, 0.0, 1.0]),
        "the robot's named material"
    );
    // The tool was merged into the upper body 0.5 m up: its mesh's origin
    // is 0.5 m up and 0.1 m along x, turned a quarter about z.
    let tool = &visuals.visuals[2];
    assert_eq!(tool.body, Some(0));
    for (got, want) in tool.pose.trans.iter().zip([0.1, 0.0, 0.5]) {
        assert!((got - want).abs() < 1e-15, "{:?}", tool.pose.trans);
    }
    assert!(
        (tool.pose.rot[1][0] - 1.0).abs() < 1e-15,
        "x turned onto y: {:?}",
        tool.pose.rot
    );
    assert!(matches!(tool.geometry, Geometry::Mesh { mesh: 0, scale } if scale == [0.001; 3]));
    // Two files on disk (the package's and the copy beside the URDF).
    assert_eq!(visuals.meshes.len(), 2);
    assert_eq!(visuals.meshes[0].bytes, b"solid part\nendsolid part\n");
    assert_eq!(visuals.warnings.len(), 1);
    let warning = visuals.warnings[0].to_string();
    assert!(
        warning.contains("arm.urdf:17:") && warning.contains("missing.stl"),
        "{warning}"
    );
    // Without the search path the package is still found: it is the
    // folder named `armpkg` that holds the URDF.
    let alone = read_visuals(&model, &[]).unwrap();
    assert_eq!(alone.visuals.len(), 4);
    std::fs::remove_dir_all(share).unwrap();
}

#[test]
fn a_trajectory_holds_rodyns_forward_kinematics() {
    let (share, urdf) = package("poses");
    let model = RuntimeModel::new(load(&urdf, LoadOptions::default()).unwrap()).unwrap();
    let scene = view::scene(&model, Default::default(), &[0.4]);
    assert_eq!(scene.bodies.len(), 1);
    assert_eq!(
        scene.bodies[0].joint,
        Joint::Revolute {
            axis: [0.0, 1.0, 0.0]
        }
    );
    assert_eq!(scene.bodies[0].placement.trans, [0.0, 0.0, 0.1]);
    assert_eq!(scene.bodies[0].com, [0.0, 0.0, 0.25]);
    assert_eq!(scene.q, [0.4]);
    // Turned by θ about y, the body's z axis is (sin θ, 0, cos θ).
    let t = [0.0, 0.5];
    let q = [vec![0.0], vec![0.7]];
    let trajectory = view::trajectory(&model, &t, &q, Vec::new()).unwrap();
    let pose = &trajectory.poses[1][0];
    assert_eq!(pose.trans, [0.0, 0.0, 0.1]);
    let z_axis = [pose.rot[0][2], pose.rot[1][2], pose.rot[2][2]];
    for (got, want) in z_axis.iter().zip([0.7f64.sin(), 0.0, 0.7f64.cos()]) {
        assert!((got - want).abs() < 1e-15, "{z_axis:?}");
    }
    std::fs::remove_dir_all(share).unwrap();
}

/// A gripper: a wrist without limits, two fingers, the second a mimic of
/// the first, and a joint whose `<limit>` states only effort and velocity.
const GRIPPER: &str = r#"<?xml version="1.0"?>
<robot name="gripper">
  <link name="palm"/>
  <link name="hand"><inertial><mass value="0.5"/><inertia ixx="1e-3" iyy="1e-3" izz="1e-3" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="left"><inertial><mass value="0.1"/><inertia ixx="1e-5" iyy="1e-5" izz="1e-5" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="right"><inertial><mass value="0.1"/><inertia ixx="1e-5" iyy="1e-5" izz="1e-5" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="thumb"><inertial><mass value="0.1"/><inertia ixx="1e-5" iyy="1e-5" izz="1e-5" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="wrist" type="continuous"><parent link="palm"/><child link="hand"/><axis xyz="0 0 1"/></joint>
  <joint name="left_finger" type="prismatic"><parent link="hand"/><child link="left"/><axis xyz="0 1 0"/>
    <limit lower="0.0" upper="0.04" effort="20" velocity="0.2"/></joint>
  <joint name="right_finger" type="prismatic"><parent link="hand"/><child link="right"/><axis xyz="0 -1 0"/>
    <limit lower="0.0" upper="0.04" effort="20" velocity="0.2"/><mimic joint="left_finger" multiplier="1" offset="0.001"/></joint>
  <joint name="thumb_joint" type="revolute"><parent link="hand"/><child link="thumb"/><axis xyz="1 0 0"/>
    <limit effort="1" velocity="1"/></joint>
</robot>
"#;

#[test]
fn sliders_get_the_urdf_limits_and_mimic_joints_follow() {
    let dir = std::env::temp_dir().join(format!("rodyn-model-view-limits-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let urdf = dir.join("gripper.urdf");
    std::fs::write(&urdf, GRIPPER).unwrap();
    let model = load(&urdf, LoadOptions::default()).unwrap();
    let limits = read_joint_limits(&model).unwrap();
    let names: Vec<&str> = model.bodies.iter().map(|b| b.joint_name.as_str()).collect();
    assert_eq!(
        names,
        ["wrist", "left_finger", "right_finger", "thumb_joint"]
    );
    assert_eq!(
        limits,
        [None, Some([0.0, 0.04]), Some([0.0, 0.04]), None],
        "continuous: none; lower = upper = 0 (URDF's defaults): none"
    );
    let scene = view::scene(&RuntimeModel::new(model).unwrap(), Default::default(), &[]);
    assert_eq!(scene.mimics.len(), 1);
    let mimic = scene.mimics[0];
    assert_eq!((mimic.follower, mimic.leader), (2, 1));
    assert_eq!((mimic.multiplier, mimic.offset), (1.0, 0.001));
    // A malformed bound names the joint and the line.
    std::fs::write(
        &urdf,
        GRIPPER.replace(
            "upper=\"0.04\" effort=\"20\" velocity=\"0.2\"/></joint>",
            "upper=\"wide\" effort=\"20\" velocity=\"0.2\"/></joint>",
        ),
    )
    .unwrap();
    let model = load(&urdf, LoadOptions::default()).unwrap();
    let e = read_joint_limits(&model).unwrap_err().to_string();
    assert!(
        e.contains("gripper.urdf:10:") && e.contains("joint `left_finger`: <limit upper=\"wide\">"),
        "{e}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
