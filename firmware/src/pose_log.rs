//! The configuration every [`POSE_EVERY_MS`], as `pose t = … ms: q = […]`
//! log lines that `cargo xtask run EXAMPLE --html` turns into a replay in
//! the viewer. Only with the `pose-log` feature: without it nothing is
//! logged and nothing reaches the image, so the checked logs, sizes and
//! instruction counts are those of the examples alone.

/// Interval between two logged configurations (ms): 50 frames a second.
pub const POSE_EVERY_MS: u32 = 20;

/// Logs `q` at `t_ms` (ms since the start of the run) when `t_ms` is a
/// multiple of [`POSE_EVERY_MS`] and the `pose-log` feature is on.
#[inline(always)]
pub fn log_pose(t_ms: u32, q: &[f32]) {
    #[cfg(feature = "pose-log")]
    if t_ms % POSE_EVERY_MS == 0 {
        defmt::println!("pose t = {} ms: q = {}", t_ms, q);
    }
    #[cfg(not(feature = "pose-log"))]
    let _ = (t_ms, q);
}
