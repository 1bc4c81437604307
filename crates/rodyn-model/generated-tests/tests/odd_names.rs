//! A model file with names Rust cannot take as they are (`odd/odd_names.toml`:
//! a keyword, line breaks, non-ASCII and empty names, digits first, a
//! name like the module's own items) compiles, and its names map to the
//! documented identifiers.

use rodyn_model_generated_tests::{frame_names, odd_names};

#[test]
fn odd_names_compile_to_distinct_identifiers() {
    assert_eq!(odd_names::NB, 3);
    assert_eq!(
        [
            odd_names::body::_U_E9,
            odd_names::body::_U_8155,
            odd_names::body::_U_E8
        ],
        [0, 1, 2]
    );
    assert_eq!(
        [
            odd_names::joint::TYPE,
            odd_names::joint::_1ST,
            odd_names::joint::SELF
        ],
        [0, 1, 2]
    );
    assert_eq!(
        [odd_names::endpoint::_EMPTY, odd_names::endpoint::MODEL_F64],
        [0, 1]
    );
    odd_names::MODEL_F64.validate().unwrap();
    odd_names::MODEL_F32.validate().unwrap();
}

#[test]
fn frames_whose_names_become_one_constant_get_suffixes() {
    assert_eq!(frame_names::NF, 3);
    assert_eq!(
        [
            frame_names::frame::A_B,
            frame_names::frame::A_B_3,
            frame_names::frame::A_B_2
        ],
        [0, 1, 2]
    );
    assert_eq!(frame_names::FRAME_NAMES, ["a.b", "a_b", "A_B_2"]);
    // Every frame on the one moving body; `A_B_2` a quarter turn about z
    // from `a_b`, its rotation composed with `a_b`'s.
    let [ab, a_b, a_b_2] = frame_names::FRAMES_F64;
    assert!([ab.body, a_b.body, a_b_2.body] == [0; 3]);
    assert_eq!(ab.placement, rodyn::spatial::Transform::IDENTITY);
    let turned = a_b.placement.rot.m;
    let composed = a_b_2.placement.rot.m;
    for r in 0..3 {
        // Columns: x of `A_B_2` is y of `a_b`, y of `A_B_2` is -x of `a_b`.
        assert!((composed[r][0] - turned[r][1]).abs() < 1e-15);
        assert!((composed[r][1] + turned[r][0]).abs() < 1e-15);
    }
}
