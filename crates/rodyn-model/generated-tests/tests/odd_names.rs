//! A model file with names Rust cannot take as they are (`odd/odd_names.toml`:
//! a keyword, line breaks, non-ASCII and empty names, digits first, a
//! name like the module's own items) compiles, and its names map to the
//! documented identifiers.

use rodyn_model_generated_tests::odd_names;

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
