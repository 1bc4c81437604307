//! Any bytes as a `.urdf` model file: loading and generating Rust may fail
//! with a diagnostic, never panic, hang or overflow the stack.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let path = std::env::temp_dir().join(format!("rodyn-fuzz-{}.urdf", std::process::id()));
    if std::fs::write(&path, data).is_ok() {
        if let Ok(model) = rodyn_model::load(&path, rodyn_model::LoadOptions::default()) {
            let _ = rodyn_model::codegen::generate(&model, "fuzzed", "fuzzed.urdf");
        }
    }
});
