//! How the screen is used on a phone, a laptop and a projector: below a width
//! the side panel is a drawer that starts closed, so the tank is what a student
//! sees first; on a big screen the whole interface is scaled up (text, plots,
//! buttons) so the back of a classroom can read it.

/// Windows narrower than this, points, are phones or narrow tablets: the side
/// panel starts closed and opens as a drawer. 700: the side panel (270) and a
/// tank of useful size (430) side by side.
pub const NARROW_WIDTH_PT: f32 = 700.0;

/// The layout the interface scale is chosen against: a laptop's 1440 × 810
/// (CSS pixels) shows everything at scale 1.
const REFERENCE_SIZE_PX: (f32, f32) = (1440.0, 810.0);

/// Range of the interface scale, automatic or chosen (0.75–2).
pub const SCALE_RANGE: std::ops::RangeInclusive<f32> = 0.75..=2.0;

/// Is a window `width_pt` wide a narrow one (see [`NARROW_WIDTH_PT`])?
pub fn is_narrow(width_pt: f32) -> bool {
    width_pt < NARROW_WIDTH_PT
}

/// The interface scale for a screen `width_px` × `height_px` CSS pixels big:
/// 1 up to a laptop's size, then growing with the smaller of the two ratios to
/// [`REFERENCE_SIZE_PX`] (a 1920 × 1080 projector gets 1.3), in steps of 0.05
/// so a small resize does not jiggle the text, at most 2.
pub fn auto_scale(width_px: f32, height_px: f32) -> f32 {
    let ratio = (width_px / REFERENCE_SIZE_PX.0).min(height_px / REFERENCE_SIZE_PX.1);
    if !ratio.is_finite() {
        return 1.0;
    }
    ((ratio * 20.0).floor() / 20.0).clamp(1.0, *SCALE_RANGE.end())
}

/// Width of the side panel opened as a drawer in a narrow window `width_pt`
/// wide: at most 320 points, leaving a strip of tank (56 points) to tap.
pub fn drawer_width(width_pt: f32) -> f32 {
    (width_pt - 56.0).clamp(200.0, 320.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phones_get_a_drawer_laptops_scale_one_projectors_bigger_text() {
        assert!(is_narrow(390.0));
        assert!(!is_narrow(1280.0));
        assert_eq!(auto_scale(390.0, 844.0), 1.0);
        assert_eq!(auto_scale(1280.0, 800.0), 1.0);
        assert_eq!(auto_scale(1920.0, 1080.0), 1.3);
        assert_eq!(auto_scale(3840.0, 2160.0), 2.0);
        assert_eq!(auto_scale(f32::NAN, 800.0), 1.0);
        assert_eq!(drawer_width(390.0), 320.0);
        assert_eq!(drawer_width(320.0), 264.0);
    }
}
