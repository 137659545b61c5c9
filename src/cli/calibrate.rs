//! `surfacelab calibrate`: a calibration file from four point pairs, the
//! image points given on the command line or clicked on the first frame in
//! a window, checked by reading it back.

use super::CalibrateArgs;
use crate::input::images::{
    Background, BitDepth, Calibration, CameraImage, CameraKind, Conversion, DEFAULT_THRESHOLD, DEFAULT_TOUCH_BAND_MM,
    ImagesError, first_frame,
};
use crate::scene;
use std::path::Path;
use std::process::ExitCode;

/// The default table points, in their order.
const CORNERS: [&str; 4] = ["far-left", "far-right", "near-right", "near-left"];

pub fn run(args: &CalibrateArgs) -> super::CommandResult {
    let out_dir = match args.out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    let background_path = args.background.as_ref().map(|b| out_dir.join(b));
    let first = first_frame(&args.images, background_path.as_deref())?;
    let frame = CameraImage::read(&first)?;
    let kind = args.kind.unwrap_or(match frame.depth() {
        BitDepth::Sixteen => CameraKind::Depth,
        BitDepth::Eight => CameraKind::Ir,
    });
    let (table_points, names) = if let Some(p) = args.table_points {
        (p, p.map(|[x, y]| format!("table point ({x}, {y})")))
    } else {
        let s = scene::load(&args.task)?;
        let (hw, hd) = (f64::from(s.table.width) / 2.0, f64::from(s.table.depth) / 2.0);
        let names = CORNERS.map(|c| format!("table's {c} corner"));
        ([[-hw, hd], [hw, hd], [hw, -hd], [-hw, -hd]], names)
    };
    let image_points = if let Some(p) = args.points {
        p
    } else {
        let title = format!("surfacelab calibrate: {}", first.display());
        let names = names.each_ref().map(String::as_str);
        let Some(p) = crate::app::pick_points(&frame, names, &title)? else {
            eprintln!("surfacelab calibrate: the window closed before four points were accepted; nothing written");
            return Ok(ExitCode::FAILURE);
        };
        p
    };
    let conversion = match kind {
        CameraKind::Ir => {
            let background = match (&args.background, &background_path) {
                (Some(name), Some(path)) => Some(Background { name: name.clone(), image: CameraImage::read(path)? }),
                _ => None,
            };
            Conversion::Ir { threshold: args.threshold.unwrap_or(DEFAULT_THRESHOLD), background }
        }
        CameraKind::Depth => {
            let table_depth_mm = match args.table_depth_mm {
                Some(d) => d,
                None => median_reading(&first, &frame)?,
            };
            Conversion::Depth { table_depth_mm, touch_band_mm: args.touch_band_mm.unwrap_or(DEFAULT_TOUCH_BAND_MM) }
        }
    };
    let origin = format!("{} (from the flags)", args.out.display());
    let calibration = Calibration::new(conversion, [frame.width, frame.height], image_points, table_points, &origin)?;
    crate::files::write_output(&args.out, calibration.to_toml().as_bytes())
        .map_err(|source| ImagesError::Write { path: args.out.display().to_string(), source })?;
    // What was written must read back, frames and all.
    Calibration::load(&args.out)?;
    eprintln!(
        "surfacelab calibrate: {} calibration for {}x{} frames written to {}",
        kind.name(),
        frame.width,
        frame.height,
        args.out.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// The table's distance as the median of a depth frame's readings.
fn median_reading(path: &Path, frame: &CameraImage) -> Result<f32, ImagesError> {
    let problem = match frame.depth() {
        BitDepth::Eight => "8-bit grey; depth frames must be 16-bit millimetres",
        BitDepth::Sixteen => "no depth readings (all 0); give --table-depth-mm",
    };
    frame
        .median_reading()
        .ok_or_else(|| ImagesError::Frame { path: path.display().to_string(), problem: problem.into() })
}

/// `"x,y x,y x,y x,y"`: four points (clap's value parser).
pub fn parse_points(s: &str) -> Result<[[f64; 2]; 4], String> {
    let points: Vec<&str> = s.split_whitespace().collect();
    if points.len() != 4 {
        return Err(format!("expected 4 points \"x,y x,y x,y x,y\", found {}", points.len()));
    }
    let mut out = [[0.0; 2]; 4];
    for (i, p) in points.iter().enumerate() {
        let (x, y) = p.split_once(',').ok_or_else(|| format!("point {} `{p}` is not x,y", i + 1))?;
        for (j, v) in [x, y].iter().enumerate() {
            let n: f64 = v.trim().parse().map_err(|_| format!("point {} `{p}`: `{v}` is not a number", i + 1))?;
            if !n.is_finite() {
                return Err(format!("point {} `{p}`: `{v}` is not finite", i + 1));
            }
            out[i][j] = n;
        }
    }
    Ok(out)
}

/// `"near,far"` millimetres (clap's value parser); the calibration's own
/// checks order and bound them.
pub fn parse_band(s: &str) -> Result<[f32; 2], String> {
    let (a, b) = s.split_once(',').ok_or_else(|| format!("`{s}` is not NEAR,FAR"))?;
    let num = |v: &str| v.trim().parse::<f32>().map_err(|_| format!("`{v}` is not a number of millimetres"));
    Ok([num(a)?, num(b)?])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_parse_as_written() {
        assert_eq!(parse_points("1,2 3.5,4  5,-6\t7,8"), Ok([[1.0, 2.0], [3.5, 4.0], [5.0, -6.0], [7.0, 8.0]]));
        assert_eq!(parse_points("1,2 3,4 5,6"), Err("expected 4 points \"x,y x,y x,y x,y\", found 3".into()));
        assert_eq!(parse_points("1,2 3,4 5,6 7;8"), Err("point 4 `7;8` is not x,y".into()));
        assert_eq!(parse_points("1,2 3,x 5,6 7,8"), Err("point 2 `3,x`: `x` is not a number".into()));
        assert_eq!(parse_band("4, 30"), Ok([4.0, 30.0]));
        assert!(parse_band("4").is_err());
    }
}
