//! Plots drawn in memory and written atomically: a full disk leaves the
//! earlier figure whole (or none), never a 0-byte `figure.png`.

use plotters::coord::Shift;
use plotters::prelude::*;

/// Draws with `draw` on a white-backed bitmap of `size` and returns its PNG
/// bytes. `draw`'s error is passed through.
pub fn png_bytes(
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), String>,
) -> Result<Vec<u8>, String> {
    let mut rgb = vec![0_u8; size.0 as usize * size.1 as usize * 3];
    {
        let area = BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area();
        draw(&area)?;
        area.present().map_err(|e| e.to_string())?;
    }
    let image = image::RgbImage::from_raw(size.0, size.1, rgb).ok_or("the plot buffer has the wrong size")?;
    let mut png = std::io::Cursor::new(Vec::new());
    image.write_to(&mut png, image::ImageFormat::Png).map_err(|e| e.to_string())?;
    Ok(png.into_inner())
}

/// Draws with `draw` as SVG text.
pub fn svg_text(
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<SVGBackend<'_>, Shift>) -> Result<(), String>,
) -> Result<String, String> {
    let mut svg = String::new();
    {
        let area = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        draw(&area)?;
        area.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}
