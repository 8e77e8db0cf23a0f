//! The rest shape of the spring–mass fish: 23 nodes, 91 springs, 12 muscles and the
//! 42 surface triangles used for the water force. Tu & Terzopoulos 1994, §3.1 and
//! Fig. 3 (layout), footnote 2 (masses and spring constants), §3.2 (surface
//! triangulation).
//!
//! The paper gives the node count, spring count, masses and stiffnesses but not the
//! coordinates of Fig. 3. This layout follows the figure (a head tip, cross-section
//! rings of four nodes, a tail section, two tail-fin nodes) with the coordinates
//! chosen by the public re-implementation vanish87/UnityFishSimulation. Everything
//! here is in *paper units*: the fish is 26 units long; [`crate::sim::body::FishBody`] scales it.
//!
//! Body frame: x forward (head at x = 0, tail towards −x), y to the fish's left,
//! z dorsal (up). Right-handed.
//!
//! ```text
//!  side view (left side, z up)                     cross-section ring k (seen from behind)
//!
//!         1----5----9---13--17                          z
//!        /|    |    |    |   |\  21                     ^
//!       0 |    |    |    |   | >-|  tail fin         b+0 ----- b+1      b+0 dorsal-left
//!        \|    |    |    |   |/  22                    | \   / |        b+1 dorsal-right
//!         4----8---12---16--20                      y <-  X    |        b+2 ventral-right
//!     head ring1 ring2 ring3 ring4 ring5                   | /   \ |        b+3 ventral-left
//!           |====|====|====|                          b+3 ----- b+2
//!        anterior middle posterior  (muscle segments)   (b = 4k + 1, k = 0..4)
//! ```
//!
//! | nodes  | what           | x     | half-width y | half-height z | mass (each) | source |
//! |--------|----------------|-------|--------------|---------------|-------------|--------|
//! | 0      | head tip       | 0     | 0            | 0             | 1.1         | paper  |
//! | 1–4    | ring 1         | −5    | 2            | 2             | 6.6         | paper  |
//! | 5–8    | ring 2         | −10   | 3            | 3             | 11.0        | paper  |
//! | 9–12   | ring 3         | −15   | 2            | 2             | 6.6         | paper  |
//! | 13–16  | ring 4         | −20   | 1            | 1             | 1.1         | paper  |
//! | 17–20  | ring 5 (tail)  | −22   | 0.8          | 0.8           | 1.1         | paper for 17–19; node 20 chosen = 1.1 so the ring is symmetric |
//! | 21, 22 | tail-fin tips  | −26   | 0            | +3, −3        | 0.165       | paper  |
//!
//! Springs (91): 4 head springs (0 to ring 1); per ring 4 edges + 2 diagonals (30);
//! per pair of neighbouring rings 4 longitudinal springs + 8 side-face diagonals (48);
//! tail fin: 21 to the dorsal pairs of rings 4 and 5, 22 to their ventral pairs,
//! plus 21–22 (9).
//!
//! # Why the fin tips are braced to ring 4 (a departure from the first layout)
//! The first layout (the re-implementation's) tied each tip to the four nodes of
//! ring 5 only. Those four anchors lie in one plane, so a tip swung round the
//! last ring to the front of it keeps every spring at its rest length: the
//! folded fin is a second rest shape. Fish fell into it and stayed there, swimming
//! at a fraction of their speed with the fin pointing forward along the body
//! (found by `FishBody::tail_fin_folded`; `shoal-census fold`, two
//! minutes, seeds 1–2: half the fish of the default reef and of *Predator and
//! school*, for 34–35 % and 40–47 % of the fish-time; 2–3 of 16 in *School meets
//! obstacle*; a converged body fell into it too). Tying each tip to two nodes of
//! ring 4 as well leaves no such twin within reach: a fin swung forward would
//! squeeze those springs from 6.4 to about 2 units; no fin folds in any demo
//! since (same census), and a fin folded by hand springs back
//! (test `a_tail_fin_folded_over_the_last_ring_springs_back`). The spring count
//! stays 91; the tail-fin tip (node 21) now couples to node 13, eight nodes away,
//! so the solver's band is eight nodes wide (`banded_cholesky.rs`).
//! Kinds (footnote 2): *cross* springs (all diagonals, in a ring or across a face,
//! e.g. S₂,₇) c = 38; *muscle* springs (the longitudinal springs of rings 1–2, 2–3,
//! 3–4, e.g. S₂,₆) c = 28; every other spring c = 30.
//!
//! Muscles (12): index `4·segment + slot`, segment 0 = anterior (rings 1–2),
//! 1 = middle (rings 2–3), 2 = posterior (rings 3–4); slot 0 = left dorsal,
//! 1 = left ventral, 2 = right dorsal, 3 = right ventral. Following §3.3 the
//! turning segments are anterior + middle and the swimming segments middle +
//! posterior (the middle segment is shared).

use glam::Vec3;

/// Number of point masses (paper §3.1).
pub const NODE_COUNT: usize = 23;
/// Number of springs (paper §3.1).
pub const SPRING_COUNT: usize = 91;
/// Number of muscle springs (paper §3.2).
pub const MUSCLE_COUNT: usize = 12;
/// Number of surface triangles of the closed body surface (chosen triangulation).
pub const TRIANGLE_COUNT: usize = 42;
/// Rest length of the paper's fish from head tip (x = 0) to tail-fin tips (x = −26),
/// in paper units.
pub const PAPER_BODY_LENGTH: f32 = 26.0;
/// Number of cross-section rings.
pub const RING_COUNT: usize = 5;
/// First node of ring k is `RING_FIRST_NODE + 4 k`.
pub const RING_FIRST_NODE: usize = 1;
/// Head-tip node.
pub const HEAD_NODE: usize = 0;
/// Upper and lower tail-fin tips.
pub const TAIL_FIN_NODES: [usize; 2] = [21, 22];

/// Cross (shear) spring constant, paper units (force per length). Paper footnote 2.
pub const CROSS_STIFFNESS: f32 = 38.0;
/// Muscle spring constant, paper units. Paper footnote 2.
pub const MUSCLE_STIFFNESS: f32 = 28.0;
/// Constant of every other spring, paper units. Paper footnote 2.
pub const OTHER_STIFFNESS: f32 = 30.0;

/// Ring geometry: (x, half-width, half-height, node mass), paper units.
const RINGS: [(f32, f32, f32, f32); RING_COUNT] = [
    (-5.0, 2.0, 2.0, 6.6),
    (-10.0, 3.0, 3.0, 11.0),
    (-15.0, 2.0, 2.0, 6.6),
    (-20.0, 1.0, 1.0, 1.1),
    (-22.0, 0.8, 0.8, 1.1),
];

/// (y sign, z sign) of the four corners of a ring, in node order.
const CORNERS: [(f32, f32); 4] = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)];

/// What a spring does; decides its stiffness (paper footnote 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum SpringKind {
    /// Diagonal that resists shearing, c = 38.
    Cross,
    /// Longitudinal spring of a muscle segment, c = 28; its rest length is actuated.
    Muscle,
    /// Any other spring, c = 30.
    Other,
}

impl SpringKind {
    /// Stiffness in paper units (force per unit length).
    pub const fn stiffness(self) -> f32 {
        match self {
            SpringKind::Cross => CROSS_STIFFNESS,
            SpringKind::Muscle => MUSCLE_STIFFNESS,
            SpringKind::Other => OTHER_STIFFNESS,
        }
    }
}

/// One spring between two nodes (`a < b`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Spring {
    pub a: usize,
    pub b: usize,
    pub kind: SpringKind,
}

/// Which third of the muscular body a muscle belongs to (paper Fig. 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum MuscleSegment {
    /// Rings 1–2: anterior turning segment.
    Anterior,
    /// Rings 2–3: posterior turning segment = anterior swimming segment.
    Middle,
    /// Rings 3–4: posterior swimming segment.
    Posterior,
}

/// Which side of the fish a muscle is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Side {
    /// +y in the body frame.
    Left,
    /// −y in the body frame.
    Right,
}

/// A muscle: which spring it is and where it sits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Muscle {
    /// Index into [`SPRINGS`].
    pub spring: usize,
    pub segment: MuscleSegment,
    pub side: Side,
    /// True for the dorsal one of the pair on this side and segment.
    pub dorsal: bool,
}

/// Index into the muscle vector u for a segment and side (both the dorsal and the
/// ventral muscle of that side: `index` and `index + 1`).
pub const fn muscle_index(segment: MuscleSegment, side: Side) -> usize {
    let s = match segment {
        MuscleSegment::Anterior => 0,
        MuscleSegment::Middle => 1,
        MuscleSegment::Posterior => 2,
    };
    let slot = match side {
        Side::Left => 0,
        Side::Right => 2,
    };
    4 * s + slot
}

/// Rest positions of the 23 nodes in paper units, body frame.
pub const REST_POSITIONS: [Vec3; NODE_COUNT] = build_positions();
/// Node masses in paper mass units (footnote 2; node 20 chosen = 1.1).
pub const MASSES: [f32; NODE_COUNT] = build_masses();
/// The 91 springs.
pub const SPRINGS: [Spring; SPRING_COUNT] = build_springs();
/// The 12 muscles in actuation order (see the module doc).
pub const MUSCLES: [Muscle; MUSCLE_COUNT] = build_muscles();
/// Surface triangles, counter-clockwise seen from outside (normal = (b−a)×(c−a) points
/// out of the body).
pub const TRIANGLES: [[usize; 3]; TRIANGLE_COUNT] = build_triangles();

/// Nodes of ring k (0-based), in corner order dorsal-left, dorsal-right,
/// ventral-right, ventral-left.
pub const fn ring_nodes(k: usize) -> [usize; 4] {
    let b = RING_FIRST_NODE + 4 * k;
    [b, b + 1, b + 2, b + 3]
}

/// The node a node maps to under the left/right mirror y → −y.
pub const fn mirror_node(i: usize) -> usize {
    if i == 0 || i >= RING_FIRST_NODE + 4 * RING_COUNT {
        return i;
    }
    let corner = (i - RING_FIRST_NODE) % 4;
    let base = i - corner;
    let mirrored = match corner {
        0 => 1,
        1 => 0,
        2 => 3,
        _ => 2,
    };
    base + mirrored
}

const fn build_positions() -> [Vec3; NODE_COUNT] {
    let mut p = [Vec3::ZERO; NODE_COUNT];
    let mut k = 0;
    while k < RING_COUNT {
        let (x, w, h, _) = RINGS[k];
        let mut c = 0;
        while c < 4 {
            let (sy, sz) = CORNERS[c];
            p[RING_FIRST_NODE + 4 * k + c] = Vec3::new(x, sy * w, sz * h);
            c += 1;
        }
        k += 1;
    }
    p[21] = Vec3::new(-26.0, 0.0, 3.0);
    p[22] = Vec3::new(-26.0, 0.0, -3.0);
    p
}

const fn build_masses() -> [f32; NODE_COUNT] {
    let mut m = [0.0; NODE_COUNT];
    m[HEAD_NODE] = 1.1;
    let mut k = 0;
    while k < RING_COUNT {
        let mut c = 0;
        while c < 4 {
            m[RING_FIRST_NODE + 4 * k + c] = RINGS[k].3;
            c += 1;
        }
        k += 1;
    }
    m[21] = 0.165;
    m[22] = 0.165;
    m
}

const fn spring(a: usize, b: usize, kind: SpringKind) -> Spring {
    if a < b {
        Spring { a, b, kind }
    } else {
        Spring { a: b, b: a, kind }
    }
}

const fn build_springs() -> [Spring; SPRING_COUNT] {
    let mut s = [spring(0, 1, SpringKind::Other); SPRING_COUNT];
    let mut n = 0;
    // Head tip to ring 1.
    let mut c = 0;
    while c < 4 {
        s[n] = spring(HEAD_NODE, RING_FIRST_NODE + c, SpringKind::Other);
        n += 1;
        c += 1;
    }
    // Ring edges and ring diagonals.
    let mut k = 0;
    while k < RING_COUNT {
        let r = ring_nodes(k);
        let mut c = 0;
        while c < 4 {
            s[n] = spring(r[c], r[(c + 1) % 4], SpringKind::Other);
            n += 1;
            c += 1;
        }
        s[n] = spring(r[0], r[2], SpringKind::Cross);
        s[n + 1] = spring(r[1], r[3], SpringKind::Cross);
        n += 2;
        k += 1;
    }
    // Between neighbouring rings: longitudinal + face diagonals.
    let mut k = 0;
    while k + 1 < RING_COUNT {
        let front = ring_nodes(k);
        let back = ring_nodes(k + 1);
        let longitudinal = if k < 3 {
            SpringKind::Muscle
        } else {
            SpringKind::Other
        };
        let mut c = 0;
        while c < 4 {
            s[n] = spring(front[c], back[c], longitudinal);
            n += 1;
            c += 1;
        }
        let mut c = 0;
        while c < 4 {
            let d = (c + 1) % 4;
            s[n] = spring(front[c], back[d], SpringKind::Cross);
            s[n + 1] = spring(front[d], back[c], SpringKind::Cross);
            n += 2;
            c += 1;
        }
        k += 1;
    }
    // Tail fin: each tip to its own side's pair (dorsal or ventral) of the last
    // two rings, so the fin cannot fold forward over the last ring (see the module
    // doc).
    let last = ring_nodes(RING_COUNT - 1);
    let before = ring_nodes(RING_COUNT - 2);
    let mut f = 0;
    while f < 2 {
        // Slots 0, 1 are dorsal, 2, 3 ventral; tip 0 (node 21) is the dorsal one.
        let first = 2 * f;
        let mut c = first;
        while c < first + 2 {
            s[n] = spring(last[c], TAIL_FIN_NODES[f], SpringKind::Other);
            s[n + 1] = spring(before[c], TAIL_FIN_NODES[f], SpringKind::Other);
            n += 2;
            c += 1;
        }
        f += 1;
    }
    s[n] = spring(TAIL_FIN_NODES[0], TAIL_FIN_NODES[1], SpringKind::Other);
    n += 1;
    assert!(n == SPRING_COUNT);
    s
}

const fn find_spring(a: usize, b: usize) -> usize {
    let mut i = 0;
    while i < SPRING_COUNT {
        let sp = SPRINGS[i];
        if (sp.a == a && sp.b == b) || (sp.a == b && sp.b == a) {
            return i;
        }
        i += 1;
    }
    panic!("no such spring");
}

const fn build_muscles() -> [Muscle; MUSCLE_COUNT] {
    // Corner per slot: left dorsal, left ventral, right dorsal, right ventral.
    const SLOT_CORNER: [usize; 4] = [0, 3, 1, 2];
    let segments = [
        MuscleSegment::Anterior,
        MuscleSegment::Middle,
        MuscleSegment::Posterior,
    ];
    let mut m = [Muscle {
        spring: 0,
        segment: MuscleSegment::Anterior,
        side: Side::Left,
        dorsal: true,
    }; MUSCLE_COUNT];
    let mut seg = 0;
    while seg < 3 {
        let mut slot = 0;
        while slot < 4 {
            let corner = SLOT_CORNER[slot];
            let a = ring_nodes(seg)[corner];
            let b = ring_nodes(seg + 1)[corner];
            m[4 * seg + slot] = Muscle {
                spring: find_spring(a, b),
                segment: segments[seg],
                side: if slot < 2 { Side::Left } else { Side::Right },
                dorsal: slot % 2 == 0,
            };
            slot += 1;
        }
        seg += 1;
    }
    m
}

const fn build_triangles() -> [[usize; 3]; TRIANGLE_COUNT] {
    let mut t = [[0; 3]; TRIANGLE_COUNT];
    let mut n = 0;
    let first = ring_nodes(0);
    let mut c = 0;
    while c < 4 {
        t[n] = [HEAD_NODE, first[c], first[(c + 1) % 4]];
        n += 1;
        c += 1;
    }
    let mut k = 0;
    while k + 1 < RING_COUNT {
        let front = ring_nodes(k);
        let back = ring_nodes(k + 1);
        let mut c = 0;
        while c < 4 {
            let d = (c + 1) % 4;
            t[n] = [front[c], back[c], back[d]];
            t[n + 1] = [front[c], back[d], front[d]];
            n += 2;
            c += 1;
        }
        k += 1;
    }
    let [dl, dr, vr, vl] = ring_nodes(RING_COUNT - 1);
    let [top, bottom] = TAIL_FIN_NODES;
    t[n] = [dl, vl, bottom];
    t[n + 1] = [dl, bottom, top];
    t[n + 2] = [dr, bottom, vr];
    t[n + 3] = [dr, top, bottom];
    t[n + 4] = [dl, top, dr];
    t[n + 5] = [vl, vr, bottom];
    n += 6;
    assert!(n == TRIANGLE_COUNT);
    t
}

#[cfg(test)]
mod tests {
    use crate::sim::body::body_layout::*;

    #[test]
    fn layout_has_paper_counts_23_nodes_91_springs_12_muscles() {
        assert_eq!(REST_POSITIONS.len(), 23);
        assert_eq!(SPRINGS.len(), 91);
        assert_eq!(MUSCLES.len(), 12);
        let muscle_springs = SPRINGS
            .iter()
            .filter(|s| s.kind == SpringKind::Muscle)
            .count();
        assert_eq!(muscle_springs, 12);
        // Footnote 2 examples: S2,6 is a muscle, S2,7 a cross spring.
        assert_eq!(SPRINGS[find_spring(2, 6)].kind, SpringKind::Muscle);
        assert_eq!(SPRINGS[find_spring(2, 7)].kind, SpringKind::Cross);
        // Every muscle spring is listed once.
        for (i, m) in MUSCLES.iter().enumerate() {
            assert_eq!(SPRINGS[m.spring].kind, SpringKind::Muscle);
            assert!(MUSCLES[i + 1..].iter().all(|o| o.spring != m.spring));
        }
    }

    #[test]
    fn masses_follow_paper_footnote() {
        let expect = |i: usize| match i {
            0 | 13..=20 => 1.1,
            1..=4 | 9..=12 => 6.6,
            5..=8 => 11.0,
            _ => 0.165,
        };
        for (i, m) in MASSES.iter().enumerate() {
            assert_eq!(*m, expect(i), "node {i}");
        }
    }

    #[test]
    fn layout_is_left_right_symmetric() {
        for (i, p) in REST_POSITIONS.iter().enumerate() {
            let q = REST_POSITIONS[mirror_node(i)];
            assert_eq!(*p, Vec3::new(q.x, -q.y, q.z), "node {i}");
            assert_eq!(MASSES[i], MASSES[mirror_node(i)]);
        }
        for s in SPRINGS {
            let m = spring(mirror_node(s.a), mirror_node(s.b), s.kind);
            assert!(SPRINGS.contains(&m), "mirror of {s:?} missing");
        }
        for m in MUSCLES {
            let partner = MUSCLES
                .iter()
                .find(|o| {
                    let (s, t) = (SPRINGS[o.spring], SPRINGS[m.spring]);
                    s.a == mirror_node(t.a) && s.b == mirror_node(t.b)
                })
                .map(|o| (o.segment, o.side, o.dorsal));
            let other_side = match m.side {
                Side::Left => Side::Right,
                Side::Right => Side::Left,
            };
            assert_eq!(partner, Some((m.segment, other_side, m.dorsal)));
        }
        for (seg, s) in [
            MuscleSegment::Anterior,
            MuscleSegment::Middle,
            MuscleSegment::Posterior,
        ]
        .into_iter()
        .enumerate()
        {
            assert_eq!(muscle_index(s, Side::Left), 4 * seg);
            assert_eq!(MUSCLES[muscle_index(s, Side::Right)].side, Side::Right);
        }
    }

    #[test]
    fn spring_graph_is_connected_and_rigid_ish() {
        // No duplicate or zero-length springs.
        for (i, s) in SPRINGS.iter().enumerate() {
            assert!(s.a != s.b);
            let len = REST_POSITIONS[s.a].distance(REST_POSITIONS[s.b]);
            assert!(len > 0.5, "spring {i} has rest length {len}");
            assert!(SPRINGS[i + 1..].iter().all(|o| (o.a, o.b) != (s.a, s.b)));
        }
        // Every node has at least three springs (needed to pin it in 3-D).
        for i in 0..NODE_COUNT {
            let degree = SPRINGS.iter().filter(|s| s.a == i || s.b == i).count();
            assert!(degree >= 3, "node {i} has {degree} springs");
        }
        // Connected: flood fill from the head.
        let mut reached = [false; NODE_COUNT];
        reached[0] = true;
        for _ in 0..NODE_COUNT {
            for s in SPRINGS {
                if reached[s.a] || reached[s.b] {
                    reached[s.a] = true;
                    reached[s.b] = true;
                }
            }
        }
        assert!(reached.iter().all(|r| *r));
    }

    #[test]
    fn surface_is_closed_with_outward_normals() {
        // Every edge is shared by exactly two triangles, in opposite directions.
        for t in TRIANGLES {
            for e in 0..3 {
                let (a, b) = (t[e], t[(e + 1) % 3]);
                let opposite = TRIANGLES
                    .iter()
                    .filter(|u| (0..3).any(|f| u[f] == b && u[(f + 1) % 3] == a))
                    .count();
                assert_eq!(opposite, 1, "edge {a}-{b}");
            }
        }
        // Closed surface: the vector area sums to zero; outward: the enclosed volume
        // (divergence theorem) is positive.
        let mut vector_area = Vec3::ZERO;
        let mut volume = 0.0;
        for [a, b, c] in TRIANGLES {
            let (pa, pb, pc) = (REST_POSITIONS[a], REST_POSITIONS[b], REST_POSITIONS[c]);
            let area_normal = 0.5 * (pb - pa).cross(pc - pa);
            vector_area += area_normal;
            volume += pa.dot(pb.cross(pc)) / 6.0;
            assert!(area_normal.length() > 0.1);
        }
        assert!(vector_area.length() < 1e-3, "{vector_area}");
        assert!(volume > 100.0, "volume {volume}");
    }
}
