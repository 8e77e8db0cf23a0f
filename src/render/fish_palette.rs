//! Animal colours. A fish's `hue` (0–1, from the simulation) picks one of a few
//! reef-fish liveries, so a shoal looks like a real community tank rather than a
//! rainbow; sharks and stingrays have their own, sober palettes, picked the same way.

/// One livery: body colour (linear RGB) and how strong its pattern is. The shader
/// reads the pattern by material: dark vertical bars on a fish, dark fin tips on a
/// shark, dark spots on a stingray's back.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Livery {
    pub rgb: [f32; 3],
    pub pattern: f32,
}

impl Livery {
    /// The instance colour: RGB, and the pattern strength in alpha.
    pub fn rgba(self) -> [f32; 4] {
        [self.rgb[0], self.rgb[1], self.rgb[2], self.pattern]
    }
}

/// The fish liveries, chosen for contrast against blue water and sand.
pub const LIVERIES: [Livery; 8] = [
    // Clownfish orange with bars.
    Livery {
        rgb: [0.95, 0.38, 0.06],
        pattern: 0.9,
    },
    // Blue tang.
    Livery {
        rgb: [0.10, 0.30, 0.95],
        pattern: 0.0,
    },
    // Yellow tang.
    Livery {
        rgb: [0.98, 0.82, 0.10],
        pattern: 0.0,
    },
    // Silver-blue sardine.
    Livery {
        rgb: [0.62, 0.72, 0.82],
        pattern: 0.25,
    },
    // Red snapper.
    Livery {
        rgb: [0.85, 0.12, 0.14],
        pattern: 0.0,
    },
    // Green chromis.
    Livery {
        rgb: [0.25, 0.85, 0.55],
        pattern: 0.0,
    },
    // Royal purple.
    Livery {
        rgb: [0.55, 0.22, 0.85],
        pattern: 0.3,
    },
    // Zebra: pale with strong bars.
    Livery {
        rgb: [0.90, 0.88, 0.80],
        pattern: 1.0,
    },
];

/// Shark backs: slate grey-blue, as most reef and requiem sharks are; the shader
/// makes the belly pale. Pattern = how dark the fin tips are.
pub const SHARK_LIVERIES: [Livery; 3] = [
    // Grey reef shark: blue-grey, dusky fin edges.
    Livery {
        rgb: [0.13, 0.17, 0.23],
        pattern: 0.35,
    },
    // Blacktip reef shark: lighter, brownish grey, black tips.
    Livery {
        rgb: [0.22, 0.22, 0.22],
        pattern: 0.9,
    },
    // Blue shark: deeper blue.
    Livery {
        rgb: [0.07, 0.13, 0.30],
        pattern: 0.1,
    },
];

/// Stingray backs: sand and mud colours, camouflage on the floor; the underside is
/// pale cream. Pattern = how strong the dark spots are.
pub const RAY_LIVERIES: [Livery; 3] = [
    // Southern stingray: sandy olive, faint spots.
    Livery {
        rgb: [0.30, 0.23, 0.13],
        pattern: 0.35,
    },
    // Leopard-spotted: pale sand, bold spots.
    Livery {
        rgb: [0.45, 0.34, 0.19],
        pattern: 0.9,
    },
    // Dark brown, almost no spots.
    Livery {
        rgb: [0.17, 0.11, 0.07],
        pattern: 0.15,
    },
];

/// The entry of `liveries` for `hue` (any finite value; wraps around).
fn pick(liveries: &[Livery], hue: f32) -> Livery {
    let h = if hue.is_finite() {
        hue.rem_euclid(1.0)
    } else {
        0.0
    };
    let index = ((h * liveries.len() as f32) as usize).min(liveries.len() - 1);
    liveries[index]
}

/// The livery for a fish's hue (any finite value; wraps around).
pub fn livery(hue: f32) -> Livery {
    pick(&LIVERIES, hue)
}

/// The livery for a shark's hue.
pub fn shark_livery(hue: f32) -> Livery {
    pick(&SHARK_LIVERIES, hue)
}

/// The livery for a stingray's hue.
pub fn ray_livery(hue: f32) -> Livery {
    pick(&RAY_LIVERIES, hue)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_hue_has_a_livery() {
        for pick in [livery, shark_livery, ray_livery] {
            for hue in [0.0, 0.5, 0.999, 1.0, -0.3, f32::NAN, 7.25] {
                let l = pick(hue);
                assert!(l.rgb.iter().all(|c| (0.0..=1.0).contains(c)));
                assert!((0.0..=1.0).contains(&l.pattern));
            }
        }
        assert_ne!(livery(0.05), livery(0.2));
    }

    #[test]
    fn sharks_are_grey_blue_and_rays_are_sandy_brown() {
        for l in SHARK_LIVERIES {
            let [r, g, b] = l.rgb;
            assert!(b >= g && g >= r, "blue-grey: {:?}", l.rgb);
            assert!(b - r < 0.35, "muted, not a bright blue: {:?}", l.rgb);
        }
        for l in RAY_LIVERIES {
            let [r, g, b] = l.rgb;
            assert!(r > g && g > b, "warm brown: {:?}", l.rgb);
        }
    }
}
