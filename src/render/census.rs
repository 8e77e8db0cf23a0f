//! The renderer's measurement script (see [`crate::census`]): the CPU cost of
//! building a frame's instances (`frame_builder.rs`).

use super::mesh::{self, Mesh};
use super::{FrameBuilder, OrbitCamera};
use crate::lab::Lab;
use crate::settings::Settings;

/// Prints what building and copying a frame's instances costs on the CPU: the
/// meshes' triangle counts, then for 5 000 and 20 000 fish in the default view
/// at 1920×1080 the median build and copy time of 200 frames, how many fish are
/// drawn in full and the fish triangles with and without the low-poly mesh.
pub(crate) fn frame_cost() {
    use std::time::Instant;
    let (fish, fish_lod) = (mesh::fish(), mesh::fish_lod());
    let triangles = |m: &Mesh| m.indices.len() / 3;
    println!(
        "triangles: fish {}, fish LOD {}, shark {}, stingray {}",
        triangles(&fish),
        triangles(&fish_lod),
        triangles(&mesh::shark()),
        triangles(&mesh::stingray())
    );
    for fish_count in [5_000_u32, 20_000] {
        let mut settings = Settings::default();
        settings.left.fish_count = fish_count;
        let lab = Lab::new(settings);
        let tank = lab.scene().tank();
        let camera = OrbitCamera::framing(tank.min_m, tank.max_m, 16.0 / 9.0);
        let mut builder = FrameBuilder::default();
        let mut staging: Vec<u8> = Vec::new();
        let runs = 200;
        let (mut build_secs, mut copy_secs) = (Vec::new(), Vec::new());
        let mut detailed = 0;
        for frame in 0..runs {
            let start = Instant::now();
            let callback =
                builder.build(&lab.runs()[0], 1.0, &camera, [1920, 1080], frame as f32, 0);
            let built = Instant::now();
            // What `queue.write_buffer` does on the CPU: a copy into staging memory.
            staging.clear();
            staging.extend_from_slice(bytemuck::cast_slice(callback.fish.as_slice()));
            std::hint::black_box(&staging);
            build_secs.push((built - start).as_secs_f64());
            copy_secs.push(built.elapsed().as_secs_f64());
            detailed = callback.fish_detailed;
        }
        build_secs.sort_by(f64::total_cmp);
        copy_secs.sort_by(f64::total_cmp);
        let tris_all_full = fish_count as usize * triangles(&fish);
        let tris_lod =
            detailed * triangles(&fish) + (fish_count as usize - detailed) * triangles(&fish_lod);
        println!(
            "{fish_count:>6} fish, 1920×1080 default view: build {:.3} ms, copy {:.3} ms (median of {runs}); \
             {detailed} detailed; fish triangles {tris_all_full} without LOD, {tris_lod} with",
            build_secs[runs / 2] * 1e3,
            copy_secs[runs / 2] * 1e3,
        );
    }
}
