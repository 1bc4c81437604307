//! The font plotters measures and draws text with.
//!
//! With plotters' `ab_glyph` feature (which cargo turns on for every figure
//! program of a workspace build, because `rodyn-sim` needs it for its GIF)
//! text needs a registered TrueType font, or drawing a label fails with
//! `FontUnavailable`. Every figure program calls [`register_sans_serif`]
//! first, so that it draws the same whether it is built alone or with the
//! workspace.

use plotters::style::{register_font, FontStyle};
use std::sync::Once;

/// Where Debian, Arch and macOS keep a sans-serif TrueType font.
const CANDIDATES: [&str; 4] = [
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
    "/Library/Fonts/Arial.ttf",
];

/// Registers the first of a few system fonts (DejaVu Sans, Liberation Sans, Arial) as plotters'
/// "sans-serif"; without one, warns once (labels will be missing).
pub fn register_sans_serif() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        for path in CANDIDATES {
            if let Ok(bytes) = std::fs::read(path) {
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                if register_font("sans-serif", FontStyle::Normal, bytes).is_ok() {
                    return;
                }
            }
        }
        eprintln!("warning: no TrueType font found (install fonts-dejavu-core); figure labels will be missing");
    });
}
