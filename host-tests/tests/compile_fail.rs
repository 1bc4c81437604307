//! An inconsistent `const` model does not compile, and says why.

#[test]
fn inconsistent_models_fail_to_compile() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/compile-fail/*.rs");
}
