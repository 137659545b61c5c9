//! The font plotters draws text with, registered once. It ships inside the
//! binary (egui's Ubuntu Light), so plots need no system fonts.

use std::sync::OnceLock;

/// The family name plots use.
pub const FONT: &str = "sans-serif";

/// Registers the bundled font; false if plotters refused it.
pub fn ensure_font() -> bool {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT, plotters::style::FontStyle::Normal, epaint_default_fonts::UBUNTU_LIGHT)
            .is_ok()
    })
}
