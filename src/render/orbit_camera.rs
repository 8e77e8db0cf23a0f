//! The orbit camera: it circles a target point inside the tank.
//!
//! Drag to rotate, wheel or pinch to zoom, right-drag (or two-finger drag) to pan.
//! The input handling reads egui's already-unified pointer and touch gestures, so
//! mouse, trackpad and touch screens all work.

use glam::{Mat4, Vec3, vec3};

/// Where the camera looks from, in spherical coordinates around `target_m`.
#[derive(Clone, Debug, PartialEq)]
pub struct OrbitCamera {
    /// Point the camera circles, metres in world space.
    pub target_m: Vec3,
    /// Angle around the vertical axis, radians; 0 looks along −z (front view).
    pub yaw_rad: f32,
    /// Angle above the horizontal, radians, within ±85°.
    pub pitch_rad: f32,
    /// Distance from the target, metres.
    pub distance_m: f32,
    /// Vertical field of view, radians.
    pub fov_y_rad: f32,
}

const PITCH_LIMIT_RAD: f32 = 85.0 * std::f32::consts::PI / 180.0;
/// The default view's direction: a little from the left (−0.18 rad) and a little
/// from above (0.22 rad), so the front glass does not hide the sand.
pub const DEFAULT_YAW_RAD: f32 = -0.18;
pub const DEFAULT_PITCH_RAD: f32 = 0.22;

/// What a scene wants the default camera to show.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Framing {
    /// This box, whole and as large as it fits, seen from this direction
    /// (radians; pitch up from level: a top view is about 1.2).
    Box {
        min_m: Vec3,
        max_m: Vec3,
        yaw_rad: f32,
        pitch_rad: f32,
    },
    /// This point from this distance, from the default direction.
    Target { target_m: Vec3, distance_m: f32 },
}
/// How a portrait view (narrower than tall: a phone held upright) sees a box
/// that is longer than it is deep: from its end (yaw −90°, so its length
/// runs up the screen) and from well above (at least 0.9 rad, about 52°), so
/// its floor fills the height the side view would leave empty. Measured on
/// the 12 × 4.5 × 8 m tank in a phone's 390 × 550 view: 60 % of the view
/// against 22 % from the front.
pub const PORTRAIT_PITCH_RAD: f32 = 0.9;

/// The direction `fitting` looks from: the one asked for, or in a portrait
/// view the end-on view from above (see [`PORTRAIT_PITCH_RAD`]).
fn direction_for(size: Vec3, yaw_rad: f32, pitch_rad: f32, aspect: f32) -> (f32, f32) {
    if aspect < 1.0 && size.x > size.z {
        (
            -std::f32::consts::FRAC_PI_2,
            pitch_rad.max(PORTRAIT_PITCH_RAD),
        )
    } else {
        (yaw_rad, pitch_rad)
    }
}
const MIN_DISTANCE_M: f32 = 1.0;
const MAX_DISTANCE_M: f32 = 60.0;

impl OrbitCamera {
    /// A view of the whole tank from the front and a little above, like standing in
    /// front of an aquarium, for a viewport of the given aspect ratio (width / height).
    pub fn framing(tank_min_m: Vec3, tank_max_m: Vec3, aspect: f32) -> Self {
        let size = tank_max_m - tank_min_m;
        Self::fitting(
            tank_min_m,
            tank_max_m,
            DEFAULT_YAW_RAD,
            DEFAULT_PITCH_RAD,
            // A little below the middle: the sand and the rocks matter more
            // than the surface.
            vec3(0.0, -size.y * 0.08, 0.0),
            aspect,
        )
    }

    /// A camera looking at the box `min_m`–`max_m` from `yaw_rad` and
    /// `pitch_rad` (radians; pitch up from level), as close as it can be with
    /// every corner in a view of `aspect` (a small margin kept), its target at
    /// the box's centre plus `target_offset_m`. A portrait view looks at a
    /// long box from its end and above instead ([`PORTRAIT_PITCH_RAD`]).
    pub fn fitting(
        min_m: Vec3,
        max_m: Vec3,
        yaw_rad: f32,
        pitch_rad: f32,
        target_offset_m: Vec3,
        aspect: f32,
    ) -> Self {
        let (yaw_rad, pitch_rad) = direction_for(max_m - min_m, yaw_rad, pitch_rad, aspect);
        Self::fitting_from(min_m, max_m, yaw_rad, pitch_rad, target_offset_m, aspect)
    }

    /// [`Self::fitting`] from exactly `yaw_rad` and `pitch_rad`.
    fn fitting_from(
        min_m: Vec3,
        max_m: Vec3,
        yaw_rad: f32,
        pitch_rad: f32,
        target_offset_m: Vec3,
        aspect: f32,
    ) -> Self {
        let center = (min_m + max_m) * 0.5;
        let size = max_m - min_m;
        let mut camera = Self {
            target_m: center + target_offset_m,
            yaw_rad,
            pitch_rad: pitch_rad.clamp(-PITCH_LIMIT_RAD, PITCH_LIMIT_RAD),
            distance_m: (size.length() * 0.5).max(MIN_DISTANCE_M),
            fov_y_rad: 40f32.to_radians(),
        };
        // Back off until every corner fits the view with a small margin.
        let corners: Vec<Vec3> = (0..8)
            .map(|i| {
                vec3(
                    if i & 1 == 0 { min_m.x } else { max_m.x },
                    if i & 2 == 0 { min_m.y } else { max_m.y },
                    if i & 4 == 0 { min_m.z } else { max_m.z },
                )
            })
            .collect();
        for _ in 0..100 {
            let m = camera.world_to_clip(aspect);
            let fits = corners.iter().all(|&c| {
                let clip = m * c.extend(1.0);
                clip.w > 0.0 && clip.x.abs() < 0.94 * clip.w && clip.y.abs() < 0.94 * clip.w
            });
            if fits || camera.distance_m >= MAX_DISTANCE_M {
                break;
            }
            camera.distance_m *= 1.03;
        }
        camera
    }

    /// The camera a scene asks for with `framing`, in a view of `aspect`.
    pub fn framed(framing: &Framing, aspect: f32) -> Self {
        match *framing {
            Framing::Box {
                min_m,
                max_m,
                yaw_rad,
                pitch_rad,
            } => Self::fitting(min_m, max_m, yaw_rad, pitch_rad, Vec3::ZERO, aspect),
            Framing::Target {
                target_m,
                distance_m,
            } => Self {
                target_m,
                yaw_rad: DEFAULT_YAW_RAD,
                pitch_rad: DEFAULT_PITCH_RAD,
                distance_m: distance_m.clamp(MIN_DISTANCE_M, MAX_DISTANCE_M),
                fov_y_rad: 40f32.to_radians(),
            },
        }
    }

    /// Camera position in world space, metres.
    pub fn eye_m(&self) -> Vec3 {
        let (sy, cy) = self.yaw_rad.sin_cos();
        let (sp, cp) = self.pitch_rad.sin_cos();
        self.target_m + self.distance_m * vec3(sy * cp, sp, cy * cp)
    }

    /// Projection × view for a viewport of the given aspect ratio (width / height).
    pub fn world_to_clip(&self, aspect: f32) -> Mat4 {
        let aspect = if aspect.is_finite() && aspect > 0.0 {
            aspect
        } else {
            1.0
        };
        let view = Mat4::look_at_rh(self.eye_m(), self.target_m, Vec3::Y);
        let proj = Mat4::perspective_rh(self.fov_y_rad, aspect, 0.1, 200.0);
        proj * view
    }

    /// Where `p_m` appears in a viewport of `aspect`, as normalised coordinates
    /// (x right, y down, both in [0, 1] when on screen); `None` behind the camera.
    pub fn project(&self, p_m: Vec3, aspect: f32) -> Option<glam::Vec2> {
        let clip = self.world_to_clip(aspect) * p_m.extend(1.0);
        if clip.w <= 1e-4 {
            return None;
        }
        let ndc = clip.truncate() / clip.w;
        Some(glam::Vec2::new(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5))
    }

    /// The ray from the eye through the viewport point `uv` (normalised as in
    /// [`Self::project`]): origin and unit direction.
    pub fn ray(&self, uv: glam::Vec2, aspect: f32) -> (Vec3, Vec3) {
        let clip_to_world = self.world_to_clip(aspect).inverse();
        let ndc = glam::Vec2::new(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0);
        let far = clip_to_world.project_point3(ndc.extend(1.0));
        let eye = self.eye_m();
        (eye, (far - eye).normalize_or(-Vec3::Z))
    }

    /// Rotates by a drag of `(dx, dy)` points.
    pub fn rotate(&mut self, dx_points: f32, dy_points: f32) {
        self.yaw_rad -= dx_points * 0.008;
        self.pitch_rad =
            (self.pitch_rad + dy_points * 0.008).clamp(-PITCH_LIMIT_RAD, PITCH_LIMIT_RAD);
    }

    /// Zooms by a factor (> 1 moves closer), as egui's `zoom_delta` reports.
    pub fn zoom(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance_m = (self.distance_m / factor).clamp(MIN_DISTANCE_M, MAX_DISTANCE_M);
        }
    }

    /// Pans the target in the view plane by a drag of `(dx, dy)` points in a viewport
    /// `viewport_height_points` tall, so the scene follows the pointer.
    pub fn pan(&mut self, dx_points: f32, dy_points: f32, viewport_height_points: f32) {
        let forward = (self.target_m - self.eye_m()).normalize_or_zero();
        let right = forward.cross(Vec3::Y).normalize_or_zero();
        let up = right.cross(forward);
        let metres_per_point =
            2.0 * self.distance_m * (self.fov_y_rad * 0.5).tan() / viewport_height_points.max(1.0);
        self.target_m += (-right * dx_points + up * dy_points) * metres_per_point;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ray_through_a_projected_point_passes_through_it() {
        let camera = OrbitCamera::framing(vec3(-6.0, 0.0, -4.0), vec3(6.0, 4.5, 4.0), 1.5);
        for p in [
            vec3(0.0, 0.0, 0.0),
            vec3(3.0, 1.0, -2.0),
            vec3(-5.0, 4.0, 3.5),
        ] {
            let uv = camera.project(p, 1.5).unwrap();
            let (origin, dir) = camera.ray(uv, 1.5);
            let to_p = p - origin;
            let miss = (to_p - dir * to_p.dot(dir)).length();
            assert!(miss < 1e-3 * to_p.length(), "{p}: {miss}");
        }
    }

    #[test]
    fn the_default_view_sees_every_corner_of_the_tank() {
        let (lo, hi) = (vec3(-6.0, 0.0, -4.0), vec3(6.0, 4.5, 4.0));
        for aspect in [16.0 / 9.0, 4.0 / 3.0, 0.6] {
            let camera = OrbitCamera::framing(lo, hi, aspect);
            let m = camera.world_to_clip(aspect);
            for i in 0..8 {
                let corner = vec3(
                    if i & 1 == 0 { lo.x } else { hi.x },
                    if i & 2 == 0 { lo.y } else { hi.y },
                    if i & 4 == 0 { lo.z } else { hi.z },
                );
                let clip = m * corner.extend(1.0);
                let ndc = clip.truncate() / clip.w;
                assert!(
                    clip.w > 0.0 && ndc.x.abs() < 1.0 && ndc.y.abs() < 1.0,
                    "{corner} → {ndc}"
                );
            }
        }
    }

    /// The share of a view of `aspect` that the tank's outline covers.
    fn tank_share(camera: &OrbitCamera, lo: Vec3, hi: Vec3, aspect: f32) -> f32 {
        let m = camera.world_to_clip(aspect);
        let mut points: Vec<glam::Vec2> = (0..8)
            .map(|i| {
                let corner = vec3(
                    if i & 1 == 0 { lo.x } else { hi.x },
                    if i & 2 == 0 { lo.y } else { hi.y },
                    if i & 4 == 0 { lo.z } else { hi.z },
                );
                let clip = m * corner.extend(1.0);
                clip.truncate().truncate() / clip.w
            })
            .collect();
        // The convex hull (monotone chain), then its area; the view is 2 × 2.
        points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        let cross = |o: glam::Vec2, a: glam::Vec2, b: glam::Vec2| (a - o).perp_dot(b - o);
        let mut hull: Vec<glam::Vec2> = Vec::new();
        for pass in [points.clone(), points.iter().rev().copied().collect()] {
            let start = hull.len();
            for p in pass {
                while hull.len() >= start + 2
                    && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
                {
                    hull.pop();
                }
                hull.push(p);
            }
            hull.pop();
        }
        let area: f32 = (0..hull.len())
            .map(|i| hull[i].perp_dot(hull[(i + 1) % hull.len()]))
            .sum::<f32>()
            .abs()
            * 0.5;
        area / 4.0
    }

    #[test]
    fn a_phone_held_upright_sees_the_tank_from_its_end_and_above_filling_the_view() {
        let (lo, hi) = (vec3(-6.0, 0.0, -4.0), vec3(6.0, 4.5, 4.0));
        // The schooling lab's view on a 390 × 844 phone (plots below it),
        // and the whole phone screen.
        for aspect in [390.0 / 550.0, 390.0 / 804.0] {
            let upright = OrbitCamera::framing(lo, hi, aspect);
            let front = OrbitCamera::fitting_from(
                lo,
                hi,
                DEFAULT_YAW_RAD,
                DEFAULT_PITCH_RAD,
                Vec3::ZERO,
                aspect,
            );
            let share = tank_share(&upright, lo, hi, aspect);
            assert!(share >= 0.45, "aspect {aspect}: the tank covers {share}");
            assert!(
                share > 2.0 * tank_share(&front, lo, hi, aspect),
                "aspect {aspect}: {share}"
            );
            assert!(upright.pitch_rad >= PORTRAIT_PITCH_RAD);
        }
        // A laptop's landscape view keeps the front view.
        let laptop = OrbitCamera::framing(lo, hi, 950.0 / 560.0);
        assert_eq!(
            (laptop.yaw_rad, laptop.pitch_rad),
            (DEFAULT_YAW_RAD, DEFAULT_PITCH_RAD)
        );
    }

    #[test]
    fn zoom_and_rotation_stay_in_bounds() {
        let mut camera = OrbitCamera::framing(Vec3::ZERO, Vec3::ONE, 1.5);
        camera.zoom(1e9);
        assert_eq!(camera.distance_m, MIN_DISTANCE_M);
        camera.zoom(f32::NAN);
        camera.zoom(0.0);
        assert_eq!(camera.distance_m, MIN_DISTANCE_M);
        camera.rotate(0.0, 1e6);
        assert!(camera.pitch_rad <= PITCH_LIMIT_RAD);
        assert!(camera.world_to_clip(0.0).is_finite());
    }

    #[test]
    fn panning_moves_the_target_sideways() {
        let mut camera = OrbitCamera::framing(Vec3::ZERO, Vec3::ONE, 1.5);
        let before = camera.target_m;
        camera.pan(100.0, 0.0, 500.0);
        assert!(camera.target_m.distance(before) > 0.0);
        assert!((camera.target_m.y - before.y).abs() < 1e-4);
    }
}
