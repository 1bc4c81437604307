//! A URDF's joint limits, for the viewer's sliders. The dynamics never
//! read them (rodyn does not enforce limits; see [`crate::urdf`]).

use crate::description::ModelDescription;
use crate::diagnostic::{Diagnostic, Location, Result};
use crate::visual::model_urdf;

/// The `[lower, upper]` range of each body's joint coordinate (rad or m),
/// by body index, from the `<limit>` of the URDF joint of the same name;
/// `None` for a body without one: a continuous or floating joint, a joint
/// a rodyn file adds, or a `<limit>` that gives no range (lower not below
/// upper, as URDF's defaults of 0 and 0 for a joint that only states its
/// effort and velocity). A model without a URDF has none.
///
/// # Errors
/// The URDF cannot be read again, or a `lower` or `upper` is not a number.
pub fn read_joint_limits(model: &ModelDescription) -> Result<Vec<Option<[f64; 2]>>> {
    let mut limits = vec![None; model.bodies.len()];
    let Some(urdf) = model_urdf(model) else {
        return Ok(limits);
    };
    let text = crate::read_model_file(urdf)
        .map_err(|e| Diagnostic::error(Location::start_of(urdf), e.to_string()))?;
    let doc = roxmltree::Document::parse(&text).map_err(|e| {
        Diagnostic::error(Location::at_offset(urdf, &text, 0), format!("not XML: {e}"))
    })?;
    let joints = doc
        .root_element()
        .children()
        .filter(|n| n.has_tag_name("joint"))
        .filter(|n| matches!(n.attribute("type"), Some("revolute" | "prismatic")));
    for joint in joints {
        let name = joint.attribute("name").unwrap_or_default();
        let Some(body) = model.bodies.iter().position(|b| b.joint_name == name) else {
            continue;
        };
        let Some(limit) = joint.children().find(|n| n.has_tag_name("limit")) else {
            continue;
        };
        let bound = |attribute: &str| -> Result<f64> {
            let Some(text_value) = limit.attribute(attribute) else {
                return Ok(0.0); // URDF's default
            };
            text_value
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    Diagnostic::error(
                        Location::at_offset(urdf, &text, limit.range().start),
                        format!(
                            "joint `{name}`: <limit {attribute}=\"{text_value}\"> is not a finite number"
                        ),
                    )
                })
        };
        let (lower, upper) = (bound("lower")?, bound("upper")?);
        if lower < upper {
            limits[body] = Some([lower, upper]);
        }
    }
    Ok(limits)
}
