//! Fish colours: a fish's `hue` (0–1, from the simulation) picks one of a few
//! reef-fish liveries, so a shoal looks like a real community tank rather than a
//! rainbow.

/// One livery: body colour (linear RGB) and how strong its dark vertical bars are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Livery {
    pub rgb: [f32; 3],
    pub bars: f32,
}

/// The liveries, chosen for contrast against blue water and sand.
pub const LIVERIES: [Livery; 8] = [
    // Clownfish orange with bars.
    Livery {
        rgb: [0.95, 0.38, 0.06],
        bars: 0.9,
    },
    // Blue tang.
    Livery {
        rgb: [0.10, 0.30, 0.95],
        bars: 0.0,
    },
    // Yellow tang.
    Livery {
        rgb: [0.98, 0.82, 0.10],
        bars: 0.0,
    },
    // Silver-blue sardine.
    Livery {
        rgb: [0.62, 0.72, 0.82],
        bars: 0.25,
    },
    // Red snapper.
    Livery {
        rgb: [0.85, 0.12, 0.14],
        bars: 0.0,
    },
    // Green chromis.
    Livery {
        rgb: [0.25, 0.85, 0.55],
        bars: 0.0,
    },
    // Royal purple.
    Livery {
        rgb: [0.55, 0.22, 0.85],
        bars: 0.3,
    },
    // Zebra: pale with strong bars.
    Livery {
        rgb: [0.90, 0.88, 0.80],
        bars: 1.0,
    },
];

/// The livery for a fish's hue (any finite value; wraps around).
pub fn livery(hue: f32) -> Livery {
    let h = if hue.is_finite() {
        hue.rem_euclid(1.0)
    } else {
        0.0
    };
    let index = ((h * LIVERIES.len() as f32) as usize).min(LIVERIES.len() - 1);
    LIVERIES[index]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_hue_has_a_livery() {
        for hue in [0.0, 0.5, 0.999, 1.0, -0.3, f32::NAN, 7.25] {
            let l = livery(hue);
            assert!(l.rgb.iter().all(|c| (0.0..=1.0).contains(c)));
        }
        assert_ne!(livery(0.05), livery(0.2));
    }
}
