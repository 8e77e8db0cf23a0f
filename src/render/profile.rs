//! The one body outline of the reef fish and of the shark, read by both bodies that
//! draw them: the rigid meshes (`mesh::fish`, `mesh::fish_lod`, `mesh::shark`, for
//! point-mass animals) and the skins over the 23-node muscle body (`body_skin`), so an
//! animal has the same shape whichever body carries it.
//!
//! # Frame and unit
//!
//! A [`Profile`] is read at `t`, the distance along the body from the tip of the
//! snout (`t = 0`) to the *tail root* (`t = 1`: where the body ends and the caudal fin
//! begins), in units of that snout-to-tail-root length. A [`Section`] is the body's
//! cross-section there, in the same unit: heights up (dorsal) from the body's centre
//! line, widths out to either flank. Fins, eyes and the tail are not part of the
//! profile: each body places its own against it.
//!
//! Each body reads it through a [`PlacedProfile`]: the profile laid along the x axis
//! of the body's own frame, in its own units, from its snout to its tail root:
//!
//! | body | unit | up | snout | tail root | snout to tail root |
//! | --- | --- | --- | --- | --- | --- |
//! | `mesh::fish`, `mesh::fish_lod` (`mesh::FISH_BODY`) | body length | +y | x = +0.5 | x = −0.5 | 1 |
//! | `mesh::shark` (`mesh::SHARK_BODY`) | body length | +y | x = +0.5 | x = −0.3 | 0.8 |
//! | `body_skin` (`FISH_BODY`, `SHARK_BODY`) | paper unit | +z | x = 0 (head node) | x = −22 (ring 5) | 22 |
//!
//! The profile fixes the shape, not the size: a rigid fish of body length B is B from
//! snout to tail root, a skinned one 22/26 B (its body length runs to the tail-fin
//! nodes), as before.
//!
//! # Which outline was kept
//!
//! Until this module each body had its own pair of formulas, alike in form but not in
//! their numbers. The skin's numbers were kept, unchanged: the muscle body is what
//! three of the five scenes draw (physics fish, the reef by default, the learning
//! lab) and what the follow camera brings close; its fins, eyes and caudal fin were
//! placed against its outline and around the body's nodes, and its outline has what
//! the rigid one lacked (a centre line rising towards the tail, a back higher than the
//! belly is deep, a fish's head a little broader at the snout). Its numbers, in paper
//! units before, are written here divided by its 22 units from snout to tail root
//! (to five significant digits: the skin moves by at most 0.0001 paper units). The
//! rigid meshes changed (in snout-to-tail-root lengths):
//!
//! - **fish**: over the first tenth behind the snout 13–34 % shallower (a less blunt
//!   head), within 5 % from t = 0.2 to 0.55, then 7–16 % deeper towards the tail and
//!   28 % at the tail root (half height 0.033 → 0.042); 10 % narrower (half width
//!   0.55 → 0.48 of the half height behind the head; 0.089 → 0.080 at the deepest);
//!   the centre line rises from −0.009 to −0.002 instead of lying at −0.010, and the
//!   back stands 1.06 half heights above it, the belly 0.94 below.
//! - **shark**: 19 % deeper (deepest half height 0.105 → 0.121) and 11 % wider
//!   (0.091 → 0.101) along most of the body, 30–40 % at the snout tip and tail root;
//!   the belly 0.76 of the back's height below the centre line instead of 0.7.
//!
//! `tests::the_rigid_mesh_and_the_skin_have_the_same_outline` measures both built
//! bodies and fails if they part again.

use glam::{Vec3, vec3};

/// How the body deepens from the snout tip to full depth over the snout, as a
/// function of `n = t / snout_length` ∈ [0, 1] (0 at the tip, 1 at full depth).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Snout {
    /// A rounded head: `(1 − (1 − n)²)^power`; a quarter ellipse at power 0.5, more
    /// tapered the larger the power.
    Rounded { power: f32 },
    /// A pointed, conical snout: `1 − (1 − n)^power`; a straight cone at power 1,
    /// more pointed the larger the power.
    Pointed { power: f32 },
}

/// One body outline along `t` ∈ [0, 1], snout to tail root (see the module doc).
/// Lengths are in snout-to-tail-root lengths, shares are plain numbers.
///
/// Half height at `t`: `min_half_height + peak_half_height · snout(t) · taper(t)`,
/// where `snout` rises from 0 to 1 over `snout_length` ([`Snout`]) and
/// `taper(t) = 1 − taper_loss · ((t − taper_start) / (1 − taper_start))^taper_power`
/// behind `taper_start` (1 before it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Profile {
    /// How far back the snout reaches: where the body is at full depth (t).
    pub snout_length: f32,
    /// The snout's shape.
    pub snout: Snout,
    /// Where the body starts to narrow towards the tail (t).
    pub taper_start: f32,
    /// How the narrowing grows behind `taper_start`: 1 linearly, larger slower at
    /// first and faster near the tail.
    pub taper_power: f32,
    /// Share of the peak half height lost by the tail root.
    pub taper_loss: f32,
    /// Half height that the snout and taper shape: at full depth the half height is
    /// this plus `min_half_height`.
    pub peak_half_height: f32,
    /// Half height everywhere on top of the shaped part: all there is at the snout
    /// tip, and the caudal peduncle's half height is this plus what the taper leaves.
    pub min_half_height: f32,
    /// Half width over half height behind the snout (below 1: laterally
    /// compressed; above 1: broader than tall).
    pub width_ratio: f32,
    /// Added to `width_ratio` at the snout tip, fading linearly to nothing at
    /// `snout_length`: a head broader than the body behind it.
    pub snout_width_ratio: f32,
    /// Height of the centre line at the snout tip (negative: below the body's
    /// axis).
    pub axis_at_snout: f32,
    /// How far the centre line rises by the tail root …
    pub axis_rise: f32,
    /// … as `t^axis_power` (1 evenly, 3 mostly near the tail, as a shark's spine
    /// turns up into the upper tail lobe).
    pub axis_power: f32,
    /// Top of the back above the centre line, in half heights.
    pub back: f32,
    /// Bottom of the belly below the centre line, in half heights (less than
    /// `back`: a flatter belly).
    pub belly: f32,
}

/// The reef fish: deep and laterally compressed, deepest 0.3 of the way back, a
/// rounded head and a slim caudal peduncle, the back more arched than the belly.
pub const FISH: Profile = Profile {
    snout_length: 0.3,
    snout: Snout::Rounded { power: 0.75 },
    taper_start: 0.3,
    taper_power: 1.3,
    taper_loss: 0.8,
    peak_half_height: 0.15455,
    min_half_height: 0.011364,
    width_ratio: 0.48,
    snout_width_ratio: 0.08,
    axis_at_snout: -0.0090909,
    axis_rise: 0.0068182,
    axis_power: 1.0,
    back: 1.06,
    belly: 0.94,
};

/// The requiem shark: a torpedo with a conical snout, deepest a third of the way
/// back, a slim caudal peduncle; the head a little broader than tall, the centre line
/// rising towards the tail, the belly flatter than the back.
pub const SHARK: Profile = Profile {
    snout_length: 0.3,
    snout: Snout::Pointed { power: 2.2 },
    taper_start: 0.33,
    taper_power: 1.4,
    taper_loss: 0.76,
    peak_half_height: 0.11364,
    min_half_height: 0.0068182,
    width_ratio: 0.82,
    snout_width_ratio: 0.3,
    axis_at_snout: -0.0068182,
    axis_rise: 0.031818,
    axis_power: 3.0,
    back: 1.0,
    belly: 0.76,
};

/// The body's cross-section at one place along it: an ellipse across, and up and
/// down from its centre line a back and a belly of their own heights.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    /// Height of the centre line above the body's axis.
    pub axis: f32,
    /// Top of the back above the centre line.
    pub back: f32,
    /// Bottom of the belly below the centre line.
    pub belly: f32,
    /// Half the width, flank to flank, at the centre line.
    pub half_width: f32,
}

impl Profile {
    /// The section at `t` (clamped to [0, 1]), in snout-to-tail-root lengths.
    pub fn section(&self, t: f32) -> Section {
        let t = t.clamp(0.0, 1.0);
        let n = (t / self.snout_length).min(1.0);
        let snout = match self.snout {
            Snout::Rounded { power } => (1.0 - (1.0 - n).powi(2)).powf(power),
            Snout::Pointed { power } => 1.0 - (1.0 - n).powf(power),
        };
        let behind = (t - self.taper_start).max(0.0) / (1.0 - self.taper_start);
        let taper = 1.0 - behind.powf(self.taper_power) * self.taper_loss;
        let half_height = self.peak_half_height * snout * taper + self.min_half_height;
        Section {
            axis: self.axis_at_snout + self.axis_rise * t.powf(self.axis_power),
            back: self.back * half_height,
            belly: self.belly * half_height,
            half_width: half_height * (self.width_ratio + self.snout_width_ratio * (1.0 - n)),
        }
    }
}

/// Which axis of a body's frame is up (dorsal); the other of y and z runs across,
/// and angle 0 of [`Section::point`] lies on its + side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Up {
    /// x forward, y up, z across: the rigid meshes.
    Y,
    /// x forward, y across (the fish's left), z up: the skins' body frame.
    Z,
}

/// A [`Profile`] laid along the x axis of one body's frame, in that body's units:
/// the one conversion each body reads the profile through (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlacedProfile {
    pub profile: Profile,
    /// x of the snout's tip.
    pub snout_x: f32,
    /// x of the tail root, below `snout_x`: the body runs along −x.
    pub tail_root_x: f32,
    /// The frame's dorsal axis.
    pub up: Up,
}

impl PlacedProfile {
    /// Snout to tail root, in the body's units.
    pub fn length(&self) -> f32 {
        self.snout_x - self.tail_root_x
    }

    /// Where `x` is along the profile (0 snout, 1 tail root).
    pub fn t(&self, x: f32) -> f32 {
        (self.snout_x - x) / self.length()
    }

    /// The cross-section at `x`, in the body's units.
    pub fn section(&self, x: f32) -> Section {
        self.profile.section(self.t(x)).scaled(self.length())
    }

    /// Height of the top of the back at `x`.
    pub fn top(&self, x: f32) -> f32 {
        self.section(x).top()
    }

    /// Height of the bottom of the belly at `x`.
    pub fn bottom(&self, x: f32) -> f32 {
        self.section(x).bottom()
    }

    /// The point of the skin at `x` and `angle` around the centre line (see
    /// [`Section::point`]), in the body's frame.
    pub fn surface(&self, x: f32, angle: f32) -> Vec3 {
        let (across, up) = self.section(x).point(angle);
        self.frame(x, across, up)
    }

    /// The tip of the snout, on the centre line.
    pub fn snout(&self) -> Vec3 {
        self.frame(self.snout_x, 0.0, self.section(self.snout_x).axis)
    }

    /// The frame's point at `x`, `across` and `up`.
    pub fn frame(&self, x: f32, across: f32, up: f32) -> Vec3 {
        match self.up {
            Up::Y => vec3(x, up, across),
            Up::Z => vec3(x, across, up),
        }
    }

    /// (x, across, up) of the frame's point `p`: the inverse of [`Self::frame`].
    pub fn unframe(&self, p: Vec3) -> (f32, f32, f32) {
        match self.up {
            Up::Y => (p.x, p.z, p.y),
            Up::Z => (p.x, p.y, p.z),
        }
    }
}

impl Section {
    /// Every length times `factor`.
    pub fn scaled(self, factor: f32) -> Self {
        Self {
            axis: self.axis * factor,
            back: self.back * factor,
            belly: self.belly * factor,
            half_width: self.half_width * factor,
        }
    }

    /// The mean of the back's height and the belly's depth.
    pub fn half_height(&self) -> f32 {
        0.5 * (self.back + self.belly)
    }

    /// Height of the top of the back.
    pub fn top(&self) -> f32 {
        self.axis + self.back
    }

    /// Height of the bottom of the belly.
    pub fn bottom(&self) -> f32 {
        self.axis - self.belly
    }

    /// The outline point at `angle` around the centre line (0 on one flank, π/2 on
    /// the top of the back, −π/2 under the belly, π on the other flank), as
    /// (across, up): an ellipse whose vertical half axis grows from the belly's depth
    /// below to the back's height above.
    pub fn point(&self, angle: f32) -> (f32, f32) {
        let (s, c) = angle.sin_cos();
        let arch = 0.5 * (self.back - self.belly);
        (
            self.half_width * c,
            self.axis + s * (self.half_height() + arch * s),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::body_skin::{self, BodyLook, BodyShape, BodySkin, MATERIAL_MASK};
    use crate::render::fish_palette::livery;
    use crate::render::mesh::{self, Material, Mesh};
    use crate::sim::body::body_layout::REST_POSITIONS;
    use std::f32::consts::FRAC_PI_2;

    #[test]
    fn sections_are_whole_and_deepest_behind_the_snout() {
        for (name, profile) in [("fish", FISH), ("shark", SHARK)] {
            let deepest = (0..=100)
                .map(|i| i as f32 / 100.0)
                .max_by(|&a, &b| {
                    let h = |t: f32| profile.section(t).half_height();
                    h(a).total_cmp(&h(b))
                })
                .unwrap();
            assert!(
                (0.25..=0.4).contains(&deepest),
                "{name}: deepest at {deepest}"
            );
            for i in 0..=100 {
                let s = profile.section(i as f32 / 100.0);
                assert!(s.back > 0.0 && s.belly > 0.0 && s.half_width > 0.0, "{s:?}");
                assert!(s.top() > s.bottom() && s.top() < 0.2 && s.bottom() > -0.2);
                let (across, up) = s.point(FRAC_PI_2);
                assert!(across.abs() < 1e-6 && (up - s.top()).abs() < 1e-6);
                let (across, up) = s.point(0.0);
                assert!((across - s.half_width).abs() < 1e-6 && (up - s.axis).abs() < 1e-6);
            }
            // Beyond either end, the end's section.
            assert_eq!(profile.section(-0.5), profile.section(0.0));
            assert_eq!(profile.section(1.5), profile.section(1.0));
        }
        // The conversion: a body 22 units long, snout at 0, tail root at −22, z up.
        let body = PlacedProfile {
            profile: FISH,
            snout_x: 0.0,
            tail_root_x: -22.0,
            up: Up::Z,
        };
        assert_eq!(body.section(-11.0), FISH.section(0.5).scaled(22.0));
        let p = body.surface(-11.0, 1.0);
        let (x, across, up) = body.unframe(p);
        assert_eq!((p.x, p.y, p.z), (x, across, up));
        let upright = PlacedProfile { up: Up::Y, ..body };
        assert_eq!(upright.surface(-11.0, 1.0), vec3(x, up, across));
    }

    /// The body's outline as built, from its rings (the vertices of one x on both
    /// flanks) among the vertices whose material word `body` accepts: for each ring,
    /// (t, top, bottom, half width), in snout-to-tail-root lengths of `placed`.
    fn outline(mesh: &Mesh, body: impl Fn(u32) -> bool, placed: &PlacedProfile) -> Vec<[f32; 4]> {
        let mut points: Vec<(f32, f32, f32)> = mesh
            .vertices
            .iter()
            .filter(|v| body(v.material))
            .map(|v| placed.unframe(Vec3::from(v.position)))
            .collect();
        points.sort_by(|a, b| b.0.total_cmp(&a.0));
        points
            .chunk_by(|a, b| a.0 == b.0)
            .filter(|ring| ring.len() >= 8 && ring.iter().any(|p| p.1 > 0.0))
            .filter(|ring| ring.iter().any(|p| p.1 < 0.0))
            .map(|ring| {
                let top = ring.iter().map(|p| p.2).fold(f32::MIN, f32::max);
                let bottom = ring.iter().map(|p| p.2).fold(f32::MAX, f32::min);
                let width = ring.iter().map(|p| p.1.abs()).fold(0.0, f32::max);
                let length = placed.length();
                [
                    placed.t(ring[0].0),
                    top / length,
                    bottom / length,
                    width / length,
                ]
            })
            .collect()
    }

    /// (top, bottom, half width) of an outline at `t`, linearly between its rings.
    fn outline_at(outline: &[[f32; 4]], t: f32) -> [f32; 3] {
        let k = outline
            .windows(2)
            .position(|w| (w[0][0]..=w[1][0]).contains(&t))
            .unwrap_or_else(|| panic!("no rings around t = {t}"));
        let (a, b) = (outline[k], outline[k + 1]);
        let u = (t - a[0]) / (b[0] - a[0]);
        std::array::from_fn(|i| a[i + 1] + (b[i + 1] - a[i + 1]) * u)
    }

    #[test]
    fn the_rigid_mesh_and_the_skin_have_the_same_outline() {
        let is = |material: Material| move |word: u32| word & MATERIAL_MASK == material as u32;
        let at_rest = |shape: BodyShape| {
            let mut out = Mesh::default();
            let look = BodyLook::fish(livery(0.2));
            BodySkin::new(shape).append_deformed(&REST_POSITIONS, &look, &mut out);
            out
        };
        for (name, rigid, rigid_body, shape, skin_body, [rigid_skin, skin_skin]) in [
            (
                "fish",
                mesh::fish(),
                &mesh::FISH_BODY,
                BodyShape::Fish,
                &body_skin::FISH_BODY,
                [Material::FishBody, Material::SkinFish],
            ),
            (
                "shark",
                mesh::shark(),
                &mesh::SHARK_BODY,
                BodyShape::Shark,
                &body_skin::SHARK_BODY,
                [Material::SharkSkin, Material::SkinShark],
            ),
        ] {
            let rigid = outline(&rigid, is(rigid_skin), rigid_body);
            let skin = outline(&at_rest(shape), is(skin_skin), skin_body);
            for t in [0.1, 0.2, 0.35, 0.5, 0.65, 0.8, 0.95] {
                let (a, b) = (outline_at(&rigid, t), outline_at(&skin, t));
                for (what, x, y) in [
                    ("top", a[0], b[0]),
                    ("bottom", a[1], b[1]),
                    ("half width", a[2], b[2]),
                ] {
                    // Rings of 14 and 18 points and their spacing along the body
                    // differ; the outlines they sample must not.
                    let tolerance = 0.002 + 0.03 * x.abs().max(y.abs());
                    assert!(
                        (x - y).abs() <= tolerance,
                        "{name} at t = {t}: {what} {x} (mesh) vs {y} (skin)"
                    );
                }
            }
        }
    }
}
