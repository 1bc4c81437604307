//! `rodyn-model tree`: a model as text, bodies indented under their parents.

use crate::description::{ForceLaw, ModelDescription};
use std::fmt::Write;

fn point(p: &[f64; 3], planar: bool) -> String {
    if planar {
        format!("({:.4}, {:.4}) m", p[0], p[1])
    } else {
        format!("({:.4}, {:.4}, {:.4}) m", p[0], p[1], p[2])
    }
}

/// The model's tree, coordinates, endpoints, drives and contacts.
#[must_use]
pub fn render_tree(m: &ModelDescription) -> String {
    let mut out = String::new();
    let planar = m.planar;
    let _ = writeln!(
        out,
        "model `{}` ({}): {} bodies, nq = {}, nv = {}, total mass {:.4} kg, gravity {}/s²",
        m.name,
        if planar { "planar" } else { "3-D" },
        m.bodies.len(),
        m.nq(),
        m.nv(),
        m.total_mass(),
        point(&m.gravity, planar)
    );
    let (idx_q, idx_v) = (m.idx_q(), m.idx_v());
    let _ = writeln!(out, "world");
    // Depth-first, children in index order, with an explicit stack.
    let mut stack: Vec<(usize, usize)> = m
        .bodies
        .iter()
        .enumerate()
        .rev()
        .filter(|(_, b)| b.parent.is_none())
        .map(|(i, _)| (i, 1))
        .collect();
    while let Some((i, depth)) = stack.pop() {
        let b = &m.bodies[i];
        let _ = writeln!(
            out,
            "{}{i:>2} {}  <- {}: {}  q[{}] v[{}]  {:.4} kg",
            "   ".repeat(depth),
            b.name,
            b.joint_name,
            b.joint.describe(),
            idx_q[i],
            idx_v[i],
            b.inertia.mass
        );
        for (c, child) in m.bodies.iter().enumerate().rev() {
            if child.parent == Some(i) {
                stack.push((c, depth + 1));
            }
        }
    }
    if !m.endpoints.is_empty() {
        let _ = writeln!(out, "endpoints:");
        for (k, e) in m.endpoints.iter().enumerate() {
            let _ = writeln!(
                out,
                "  {k:>2} {} on {} at {}",
                e.name,
                m.body_name(e.body),
                point(&e.position, planar)
            );
        }
    }
    if !m.force_elements.is_empty() || !m.motors.is_empty() {
        let _ = writeln!(out, "drives:");
        for f in &m.force_elements {
            let path = f
                .path
                .iter()
                .map(|&e| m.endpoints[e].name.as_str())
                .collect::<Vec<_>>();
            let params = match f.law {
                ForceLaw::Spring { stiffness, rest_length, cubic_stiffness } => {
                    format!("k = {stiffness} N/m, k3 = {cubic_stiffness} N/m³, rest length {rest_length} m")
                }
                ForceLaw::Damper { damping } => format!("d = {damping} N s/m"),
                ForceLaw::Muscle { max_isometric_force, optimal_fiber_length, tendon_slack_length, .. } => format!(
                    "F_max = {max_isometric_force} N, l_opt = {optimal_fiber_length} m, l_slack = {tendon_slack_length} m"
                ),
            };
            let _ = writeln!(
                out,
                "  {} {}: {} ({params})",
                f.law.kind(),
                f.name,
                path.join(" -> ")
            );
        }
        for motor in &m.motors {
            let _ = writeln!(
                out,
                "  motor {} on {}: gear ratio {}, k_t = {} N m/A, rotor {} kg m²",
                motor.name,
                m.bodies[motor.body].joint_name,
                motor.gear_ratio,
                motor.torque_constant,
                motor.rotor_inertia
            );
        }
    }
    if !m.contacts.is_empty() {
        let _ = writeln!(out, "contacts:");
        for c in &m.contacts {
            let _ = writeln!(
                out,
                "  {} at {}: k = {} N/m, d = {} N s/m, mu = {}",
                c.name, m.endpoints[c.endpoint].name, c.stiffness, c.damping, c.friction
            );
        }
    }
    out
}
