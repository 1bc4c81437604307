//! The payload scene of the firmware's `payload_update` example, on the
//! host: the identified payload is close to the true one, and the tracking
//! error falls once the identified model is swapped in.

use rodyn::update::DoubleBuffered;
use rodyn_scenarios::panda;
use rodyn_scenarios::payload_scene::{PayloadScene, SWAP_AT, TRUE_PAYLOAD};

#[test]
fn identified_payload_is_swapped_in_and_the_tracking_error_falls() {
    let mut models = DoubleBuffered::new(panda::MODEL_F32);
    let mut scene = PayloadScene::new(&mut models).unwrap();
    let mut found = None;
    while !scene.done() {
        let outcome = scene.step().unwrap();
        if let Some(payload) = outcome.swapped {
            assert_eq!(outcome.tick, SWAP_AT);
            found = Some(payload);
        }
    }
    let found = found.expect("no payload identified");
    let (before, after) = (scene.before, scene.after);
    println!(
        "identified {} kg at {:?} m (true {} kg at {:?}); rms tracking error {:.3e} -> {:.3e} rad, max {:.3e} -> {:.3e} rad",
        found.mass, found.com, TRUE_PAYLOAD.mass, TRUE_PAYLOAD.com,
        before.rms(), after.rms(), before.max, after.max
    );
    // Mass within 2 %, centre of mass within 5 mm.
    assert!((found.mass - TRUE_PAYLOAD.mass).abs() < 0.02 * TRUE_PAYLOAD.mass);
    assert!((found.com - TRUE_PAYLOAD.com).norm() < 5e-3);
    // The error falls at least fivefold.
    assert!(after.rms() < 0.2 * before.rms());
    assert!(after.max < 0.2 * before.max);
}
