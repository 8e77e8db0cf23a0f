//! Draws the aquarium with wgpu inside egui, the way egui's own `custom3d_wgpu` demo
//! does: GPU resources live in egui-wgpu's callback resources, the frame's data is
//! uploaded and the scene rendered in `prepare`, and `paint` only draws the result.
//!
//! The scene is rendered into an offscreen image of its own (with a depth buffer and
//! 4× MSAA where the tier allows), then copied into egui's pass. That keeps the 3D
//! pass independent of how eframe configured its framebuffer on each tier.
//!
//! Passes, in order: the room and the water volume behind everything (a full-screen
//! triangle that ray-casts the tank box), static meshes (sand, rocks, pillars, tank
//! frame), deformed bodies (physical fish skinned to their nodes on the CPU each
//! frame, `body_skin`), instanced animals (fish near and far, sharks, stingrays),
//! and the translucent water surface.
//!
//! Several 3D views can be drawn in one frame (compare mode shows two tanks), each
//! its own paint callback with its own `view_id`. egui runs every callback's
//! `prepare` before any `paint`, so each view keeps its own uniforms, instances,
//! static mesh and offscreen image ([`ViewState`], in a [`ViewCache`]); pipelines,
//! shaders, the sampler and the animal meshes are shared.

use std::ops::Range;
use std::sync::Arc;

use bytemuck::{Pod, Zeroable};
use eframe::egui;
use eframe::egui_wgpu::{self, CallbackResources, CallbackTrait, ScreenDescriptor};
use eframe::wgpu;
use eframe::wgpu::util::DeviceExt;
use glam::{Mat4, Vec3};

use super::mesh::{self, Mesh, Vertex};
use super::render_tier::{RenderCaps, SCENE_COLOR_FORMAT, SCENE_DEPTH_FORMAT};
use crate::sim::common::spare::release_spare;

/// Per-frame constants shared by every scene shader (`Scene` in `scene.wgsl`).
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
pub struct SceneUniforms {
    pub world_to_clip: [[f32; 4]; 4],
    pub clip_to_world: [[f32; 4]; 4],
    /// Camera position; w = animation time in seconds (caustics, ripples).
    pub eye_m: [f32; 4],
    /// Tank's lower corner; w = water turbidity (fog density per metre).
    pub tank_min_m: [f32; 4],
    /// Tank's upper corner; w = unused.
    pub tank_max_m: [f32; 4],
    /// Unit vector towards the light; w = unused.
    pub sun_dir: [f32; 4],
}

impl SceneUniforms {
    pub fn new(
        world_to_clip: Mat4,
        eye_m: Vec3,
        tank_min_m: Vec3,
        tank_max_m: Vec3,
        time_secs: f32,
    ) -> Self {
        /// Fog density per metre of water: about half the light is lost over 8 m,
        /// enough that the back of the tank looks deep without hiding fish.
        const TURBIDITY_PER_M: f32 = 0.085;
        let sun = Vec3::new(0.25, 1.0, 0.35).normalize_or_zero();
        Self {
            world_to_clip: world_to_clip.to_cols_array_2d(),
            clip_to_world: world_to_clip.inverse().to_cols_array_2d(),
            eye_m: eye_m.extend(time_secs).to_array(),
            tank_min_m: tank_min_m.extend(TURBIDITY_PER_M).to_array(),
            tank_max_m: tank_max_m.extend(0.0).to_array(),
            sun_dir: sun.extend(0.0).to_array(),
        }
    }
}

/// One animal to draw, fish, shark or stingray (`FishInstance` in `scene.wgsl`).
/// 48 bytes.
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
pub struct FishInstance {
    pub position_m: [f32; 3],
    pub body_length_m: f32,
    /// Unit forward direction.
    pub forward: [f32; 3],
    /// Tail-beat phase (a stingray: wing-beat phase), radians.
    pub tail_phase_rad: f32,
    /// RGB body colour; a = pattern strength in [0, 1] (see `fish_palette::Livery`).
    pub color: [f32; 4],
}

/// The static part of the scene (floor, frame, obstacles), rebuilt when the world is.
#[derive(Clone, Debug)]
pub struct StaticScene {
    /// Changes whenever the mesh changes, and differs between worlds (the frame
    /// builder draws it from one counter for the whole program); the GPU copy is
    /// re-uploaded when it changes.
    pub generation: u64,
    pub mesh: Arc<Mesh>,
}

/// Everything one frame of one 3D view draws. Built by the app on the CPU,
/// consumed in `prepare`.
pub struct SceneCallback {
    /// Which 3D view this is: each keeps its own GPU state, so several views can be
    /// drawn in one frame (compare mode: 0 and 1). At most one callback per view id
    /// per frame.
    pub view_id: u32,
    pub uniforms: SceneUniforms,
    /// The fish. The first `fish_detailed` are drawn with `mesh::fish`, the rest
    /// (small on screen) with the low-poly `mesh::fish_lod`.
    pub fish: Arc<Vec<FishInstance>>,
    pub fish_detailed: usize,
    /// Sharks, drawn with `mesh::shark`, swimming like the fish.
    pub sharks: Arc<Vec<FishInstance>>,
    /// Stingrays, drawn with `mesh::stingray`; `tail_phase_rad` drives the wing beat.
    pub rays: Arc<Vec<FishInstance>>,
    pub statics: StaticScene,
    /// World-space meshes rebuilt every frame: physical fish, filled with
    /// `BodySkin::append_deformed`. Uploaded each frame into a buffer of the view
    /// that grows as needed; empty costs nothing.
    pub bodies: Arc<Mesh>,
    /// Size of the 3D view in physical pixels.
    pub size_px: [u32; 2],
}

/// State kept per 3D view, keyed by view id: created on first use; a view not drawn
/// for [`ViewCache::STALE_AFTER_FRAMES`] frames is dropped, and when a new view
/// would make more than [`ViewCache::MAX_VIEWS`], the one drawn least recently goes
/// (never one drawn in the current frame: its `paint` is still to come).
///
/// Frames are counted without help from egui: each view is drawn at most once a
/// frame, so a view drawn a second time means a new frame has begun.
#[derive(Debug)]
pub struct ViewCache<T> {
    frame: u64,
    drawn_this_frame: Vec<u32>,
    entries: Vec<ViewEntry<T>>,
}

#[derive(Debug)]
struct ViewEntry<T> {
    view_id: u32,
    last_frame: u64,
    state: T,
}

impl<T> Default for ViewCache<T> {
    fn default() -> Self {
        Self {
            frame: 0,
            drawn_this_frame: Vec::new(),
            entries: Vec::new(),
        }
    }
}

impl<T> ViewCache<T> {
    /// Views kept at most (unless more are drawn in one frame): compare mode needs
    /// two; four leaves room without holding much GPU memory.
    pub const MAX_VIEWS: usize = 4;
    /// A view not drawn for this many frames (5 s at 60 FPS) is dropped.
    pub const STALE_AFTER_FRAMES: u64 = 300;

    /// Marks `view_id` as drawn in this frame and returns its state, made by `make`
    /// if the view is new; drops views by the rule above first.
    pub fn draw(&mut self, view_id: u32, make: impl FnOnce() -> T) -> &mut T {
        if self.drawn_this_frame.contains(&view_id) {
            self.frame += 1;
            self.drawn_this_frame.clear();
        }
        self.drawn_this_frame.push(view_id);
        let frame = self.frame;
        self.entries
            .retain(|e| e.view_id == view_id || frame - e.last_frame <= Self::STALE_AFTER_FRAMES);
        let index = match self.entries.iter().position(|e| e.view_id == view_id) {
            Some(index) => index,
            None => {
                while self.entries.len() >= Self::MAX_VIEWS {
                    let oldest = self
                        .entries
                        .iter()
                        .enumerate()
                        .filter(|(_, e)| e.last_frame < frame)
                        .min_by_key(|(_, e)| e.last_frame)
                        .map(|(i, _)| i);
                    let Some(oldest) = oldest else { break };
                    self.entries.swap_remove(oldest);
                }
                self.entries.push(ViewEntry {
                    view_id,
                    last_frame: frame,
                    state: make(),
                });
                self.entries.len() - 1
            }
        };
        let entry = &mut self.entries[index];
        entry.last_frame = frame;
        &mut entry.state
    }

    /// The state of `view_id`, if it is kept.
    pub fn get(&self, view_id: u32) -> Option<&T> {
        self.entries
            .iter()
            .find(|e| e.view_id == view_id)
            .map(|e| &e.state)
    }

    /// The view ids kept, in no particular order.
    pub fn view_ids(&self) -> impl Iterator<Item = u32> + '_ {
        self.entries.iter().map(|e| e.view_id)
    }
}

/// A mesh on the GPU.
struct GpuMesh {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

impl GpuMesh {
    /// `None` for an empty mesh (nothing to draw, and wgpu rejects empty buffers
    /// on some tiers).
    fn upload(device: &wgpu::Device, label: &str, mesh: &Mesh) -> Option<Self> {
        if mesh.indices.is_empty() {
            return None;
        }
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&mesh.vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(&mesh.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Some(Self {
            vertices,
            indices,
            index_count: mesh.indices.len() as u32,
        })
    }
}

/// A mesh rewritten every frame (deformed bodies), in buffers that only grow.
struct DynamicMesh {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    /// The indices last written: they stay the same from frame to frame while the
    /// same bodies are drawn, and are then not written again.
    written_indices: Vec<u32>,
}

impl DynamicMesh {
    /// Bytes a buffer holds at first; it grows to the next power of two.
    const FIRST_CAPACITY: u64 = 1 << 16;

    fn buffer(
        device: &wgpu::Device,
        label: &str,
        size: u64,
        usage: wgpu::BufferUsages,
    ) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size,
            usage: usage | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    fn new(device: &wgpu::Device) -> Self {
        Self {
            vertices: Self::buffer(
                device,
                "bodies",
                Self::FIRST_CAPACITY,
                wgpu::BufferUsages::VERTEX,
            ),
            indices: Self::buffer(
                device,
                "bodies",
                Self::FIRST_CAPACITY,
                wgpu::BufferUsages::INDEX,
            ),
            index_count: 0,
            written_indices: Vec::new(),
        }
    }

    /// Writes `mesh`, growing a buffer when it is too small; draws nothing if the
    /// mesh is empty or larger than the device allows.
    fn write(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, mesh: &Mesh) {
        self.index_count = 0;
        if mesh.indices.is_empty() || mesh.vertices.is_empty() {
            return;
        }
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&mesh.vertices);
        let index_bytes: &[u8] = bytemuck::cast_slice(&mesh.indices);
        let grown = |buffer: &wgpu::Buffer, needed: usize| -> Option<Option<u64>> {
            let needed = needed as u64;
            if needed <= buffer.size() {
                return Some(None);
            }
            let max = device.limits().max_buffer_size;
            (needed <= max).then(|| Some(needed.next_power_of_two().min(max)))
        };
        let (Some(vertex_size), Some(index_size)) = (
            grown(&self.vertices, vertex_bytes.len()),
            grown(&self.indices, index_bytes.len()),
        ) else {
            return;
        };
        if let Some(size) = vertex_size {
            self.vertices = Self::buffer(device, "bodies", size, wgpu::BufferUsages::VERTEX);
        }
        if let Some(size) = index_size {
            self.indices = Self::buffer(device, "bodies", size, wgpu::BufferUsages::INDEX);
            self.written_indices.clear();
        }
        queue.write_buffer(&self.vertices, 0, vertex_bytes);
        if self.written_indices != mesh.indices {
            queue.write_buffer(&self.indices, 0, index_bytes);
            self.written_indices.clone_from(&mesh.indices);
            release_spare(&mut self.written_indices, 4096);
        }
        self.index_count = mesh.indices.len() as u32;
    }
}

/// The instanced meshes, by what they draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Animal {
    Fish,
    FarFish,
    Shark,
    Ray,
}

impl Animal {
    const ALL: [Animal; 4] = [Animal::Fish, Animal::FarFish, Animal::Shark, Animal::Ray];

    fn mesh(self) -> Mesh {
        match self {
            Animal::Fish => mesh::fish(),
            Animal::FarFish => mesh::fish_lod(),
            Animal::Shark => mesh::shark(),
            Animal::Ray => mesh::stingray(),
        }
    }
}

/// Where each kind of animal sits in a view's instance buffer, in instances:
/// near fish, far fish, sharks, rays, one after another.
fn instance_ranges(frame: &SceneCallback) -> [(Animal, Range<u32>); 4] {
    let detailed = frame.fish_detailed.min(frame.fish.len()) as u32;
    let fish = frame.fish.len() as u32;
    let sharks = fish + frame.sharks.len() as u32;
    let rays = sharks + frame.rays.len() as u32;
    [
        (Animal::Fish, 0..detailed),
        (Animal::FarFish, detailed..fish),
        (Animal::Shark, fish..sharks),
        (Animal::Ray, sharks..rays),
    ]
}

struct Targets {
    size_px: [u32; 2],
    /// Multisampled colour (only when MSAA is on).
    msaa_color: Option<wgpu::TextureView>,
    depth: wgpu::TextureView,
    /// The single-sample image that `paint` copies into egui's pass.
    color: wgpu::TextureView,
    blit_bind_group: wgpu::BindGroup,
}

/// The GPU state of one 3D view.
struct ViewState {
    uniform_buffer: wgpu::Buffer,
    uniform_bind_group: wgpu::BindGroup,
    /// Every animal of the view, by kind in `instance_ranges` order.
    instances: wgpu::Buffer,
    instance_capacity: usize,
    ranges: [(Animal, Range<u32>); 4],
    statics: Option<GpuMesh>,
    static_generation: Option<u64>,
    /// Deformed bodies; made when the view first draws some.
    bodies: Option<DynamicMesh>,
    targets: Option<Targets>,
    /// What the offscreen image now shows: a frame with the same inputs is not
    /// drawn again, only shown (a paused tank under a still camera costs one blit
    /// a frame while the teacher works the panels).
    drawn: DrawnInputs,
}

/// The inputs of the last frame a view drew, to tell whether the next frame would
/// draw the same picture. Exact: every field of [`SceneCallback`] that reaches the
/// GPU is compared, byte for byte. While the tank runs, the uniforms (simulated
/// time, camera) change every frame, so the instances and bodies (megabytes with
/// many muscle fish) are not copied then: they are recorded on the first frame
/// after a still one, and compared in place from then on.
#[derive(Default)]
struct DrawnInputs {
    uniforms: Option<SceneUniforms>,
    /// Did the uniforms change at the last frame?
    uniforms_moving: bool,
    /// The rest of the inputs, when recorded (`content_valid`).
    content: Vec<u8>,
    content_valid: bool,
}

impl DrawnInputs {
    /// The inputs other than the uniforms, as byte slices in a fixed order.
    fn parts(frame: &SceneCallback) -> ([u64; 7], [&[u8]; 5]) {
        let header = [
            frame.statics.generation,
            frame.fish_detailed as u64,
            frame.fish.len() as u64,
            frame.sharks.len() as u64,
            frame.rays.len() as u64,
            frame.bodies.vertices.len() as u64,
            frame.bodies.indices.len() as u64,
        ];
        let slices = [
            bytemuck::cast_slice(frame.fish.as_slice()),
            bytemuck::cast_slice(frame.sharks.as_slice()),
            bytemuck::cast_slice(frame.rays.as_slice()),
            bytemuck::cast_slice(&frame.bodies.vertices),
            bytemuck::cast_slice(&frame.bodies.indices),
        ];
        (header, slices)
    }

    fn record(&mut self, frame: &SceneCallback) {
        let (header, slices) = Self::parts(frame);
        self.content.clear();
        self.content.extend_from_slice(bytemuck::bytes_of(&header));
        for part in slices {
            self.content.extend_from_slice(part);
        }
        // After a frame of 300 muscle fish this copy was 3.5 MB; a tank back
        // at 10 fish needs a tenth of it (issue 35).
        release_spare(&mut self.content, 64 * 1024);
        self.content_valid = true;
    }

    fn content_equals(&self, frame: &SceneCallback) -> bool {
        if !self.content_valid {
            return false;
        }
        let (header, slices) = Self::parts(frame);
        let mut rest = self.content.as_slice();
        for part in std::iter::once(bytemuck::bytes_of(&header)).chain(slices) {
            match rest.split_at_checked(part.len()) {
                Some((head, tail)) if head == part => rest = tail,
                _ => return false,
            }
        }
        rest.is_empty()
    }

    /// Takes `frame`'s inputs into account and says whether they equal the last
    /// frame's.
    fn same_as_last(&mut self, frame: &SceneCallback) -> bool {
        let uniforms = bytemuck::bytes_of(&frame.uniforms);
        if self.uniforms.as_ref().map(bytemuck::bytes_of) != Some(uniforms) {
            let was_moving = self.uniforms_moving;
            self.uniforms = Some(frame.uniforms);
            self.uniforms_moving = true;
            if was_moving {
                self.content_valid = false;
            } else {
                self.record(frame);
            }
            return false;
        }
        self.uniforms_moving = false;
        if self.content_equals(frame) {
            return true;
        }
        self.record(frame);
        false
    }

    /// Forgets the last frame: the next one is drawn whatever it holds.
    fn forget(&mut self) {
        self.content_valid = false;
    }
}

/// GPU resources of the scene renderer, kept in egui-wgpu's callback resources.
pub struct SceneRenderer {
    caps: RenderCaps,
    uniform_layout: wgpu::BindGroupLayout,
    background_pipeline: wgpu::RenderPipeline,
    static_pipeline: wgpu::RenderPipeline,
    /// Fish and sharks (`vs_fish`).
    swim_pipeline: wgpu::RenderPipeline,
    /// Stingrays (`vs_ray`).
    ray_pipeline: wgpu::RenderPipeline,
    /// Deformed bodies in world space (`vs_body`), both faces drawn.
    body_pipeline: wgpu::RenderPipeline,
    surface_pipeline: wgpu::RenderPipeline,
    blit_pipeline: wgpu::RenderPipeline,
    blit_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    /// One mesh per `Animal`, in `Animal::ALL` order.
    animal_meshes: Vec<Option<GpuMesh>>,
    views: ViewCache<ViewState>,
}

const SCENE_SHADER: &str = include_str!("../../shaders/scene.wgsl");
const BLIT_SHADER: &str = include_str!("../../shaders/blit.wgsl");
/// Instances a view's buffer holds at first; it grows to the next power of two.
const FIRST_INSTANCE_CAPACITY: usize = 256;
impl SceneRenderer {
    /// Creates the pipelines and registers the renderer with egui's callback
    /// resources. Returns what this adapter allows.
    pub fn install(render_state: &egui_wgpu::RenderState) -> RenderCaps {
        let caps = RenderCaps::of_adapter(&render_state.adapter);
        let renderer = Self::new(&render_state.device, render_state.target_format, caps);
        render_state
            .renderer
            .write()
            .callback_resources
            .insert(renderer);
        caps
    }

    fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat, caps: RenderCaps) -> Self {
        let scene_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("scene.wgsl"),
            source: wgpu::ShaderSource::Wgsl(SCENE_SHADER.into()),
        });
        let blit_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("blit.wgsl"),
            source: wgpu::ShaderSource::Wgsl(BLIT_SHADER.into()),
        });
        let uniform_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("scene uniforms"), // words: a GPU debug label
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(size_of::<SceneUniforms>() as u64),
                },
                count: None,
            }],
        });
        let scene_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("scene"),
            bind_group_layouts: &[Some(&uniform_layout)],
            immediate_size: 0,
        });

        let vertex_layout = wgpu::VertexBufferLayout {
            array_stride: size_of::<Vertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Uint32, 2 => Float32x3, 3 => Unorm8x4],
        };
        let instance_layout = wgpu::VertexBufferLayout {
            array_stride: size_of::<FishInstance>() as u64,
            step_mode: wgpu::VertexStepMode::Instance,
            attributes: &wgpu::vertex_attr_array![4 => Float32x4, 5 => Float32x4, 6 => Float32x4],
        };
        let multisample = wgpu::MultisampleState {
            count: caps.msaa_samples,
            ..Default::default()
        };
        let depth = |write: bool| wgpu::DepthStencilState {
            format: SCENE_DEPTH_FORMAT,
            depth_write_enabled: Some(write),
            depth_compare: Some(wgpu::CompareFunction::LessEqual),
            stencil: wgpu::StencilState::default(),
            bias: wgpu::DepthBiasState::default(),
        };
        let pipeline = |label: &str,
                        vs: &str,
                        fs: &str,
                        buffers: &[Option<wgpu::VertexBufferLayout<'_>>],
                        cull: Option<wgpu::Face>,
                        depth_state: wgpu::DepthStencilState,
                        blend: Option<wgpu::BlendState>| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&scene_layout),
                vertex: wgpu::VertexState {
                    module: &scene_module,
                    entry_point: Some(vs),
                    compilation_options: Default::default(),
                    buffers,
                },
                primitive: wgpu::PrimitiveState {
                    cull_mode: cull,
                    ..Default::default()
                },
                depth_stencil: Some(depth_state),
                multisample,
                fragment: Some(wgpu::FragmentState {
                    module: &scene_module,
                    entry_point: Some(fs),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: SCENE_COLOR_FORMAT,
                        blend,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
        };
        let background_pipeline = pipeline(
            "background",
            "vs_background",
            "fs_background",
            &[],
            None,
            wgpu::DepthStencilState {
                depth_compare: Some(wgpu::CompareFunction::Always),
                ..depth(false)
            },
            None,
        );
        let static_pipeline = pipeline(
            "static meshes", // words: a GPU debug label
            "vs_static",
            "fs_lit",
            &[Some(vertex_layout.clone())],
            Some(wgpu::Face::Back),
            depth(true),
            None,
        );
        // Fins are double-sided geometry; bodies are closed: back-face culling.
        let swim_pipeline = pipeline(
            "fish and sharks", // words: a GPU debug label
            "vs_fish",
            "fs_lit",
            &[Some(vertex_layout.clone()), Some(instance_layout.clone())],
            Some(wgpu::Face::Back),
            depth(true),
            None,
        );
        let ray_pipeline = pipeline(
            "stingrays",
            "vs_ray",
            "fs_lit",
            &[Some(vertex_layout.clone()), Some(instance_layout)],
            Some(wgpu::Face::Back),
            depth(true),
            None,
        );
        // Deformed bodies: fins are single sheets and `fs_lit` turns normals to the
        // eye, so no culling (which also keeps a mirrored placement visible).
        let body_pipeline = pipeline(
            "deformed bodies", // words: a GPU debug label
            "vs_body",
            "fs_lit",
            &[Some(vertex_layout)],
            None,
            depth(true),
            None,
        );
        let surface_pipeline = pipeline(
            "water surface", // words: a GPU debug label
            "vs_surface",
            "fs_surface",
            &[],
            None,
            depth(false),
            Some(wgpu::BlendState::ALPHA_BLENDING),
        );

        let blit_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("blit"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: true },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: false,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let blit_pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("blit"),
            bind_group_layouts: &[Some(&blit_layout)],
            immediate_size: 0,
        });
        let blit_pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("blit"),
            layout: Some(&blit_pipeline_layout),
            vertex: wgpu::VertexState {
                module: &blit_module,
                entry_point: Some("vs_blit"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &blit_module,
                // The scene image is gamma-encoded; an sRGB target wants linear values.
                entry_point: Some(if target_format.is_srgb() {
                    "fs_blit_to_linear"
                } else {
                    "fs_blit"
                }),
                compilation_options: Default::default(),
                targets: &[Some(target_format.into())],
            }),
            multiview_mask: None,
            cache: None,
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("blit"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });

        let animal_meshes = Animal::ALL
            .iter()
            .map(|animal| GpuMesh::upload(device, &format!("{animal:?} mesh"), &animal.mesh()))
            .collect();

        Self {
            caps,
            uniform_layout,
            background_pipeline,
            static_pipeline,
            swim_pipeline,
            ray_pipeline,
            body_pipeline,
            surface_pipeline,
            blit_pipeline,
            blit_layout,
            sampler,
            animal_meshes,
            views: ViewCache::default(),
        }
    }

    fn instance_buffer(device: &wgpu::Device, capacity: usize) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("animal instances"), // words: a GPU debug label
            size: (capacity * size_of::<FishInstance>()) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    /// The GPU state of a view that is drawn for the first time.
    fn new_view(&self, device: &wgpu::Device) -> ViewState {
        let uniform_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("scene uniforms"), // words: a GPU debug label
            size: size_of::<SceneUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let uniform_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene uniforms"), // words: a GPU debug label
            layout: &self.uniform_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniform_buffer.as_entire_binding(),
            }],
        });
        ViewState {
            uniform_buffer,
            uniform_bind_group,
            instances: Self::instance_buffer(device, FIRST_INSTANCE_CAPACITY),
            instance_capacity: FIRST_INSTANCE_CAPACITY,
            ranges: Animal::ALL.map(|animal| (animal, 0..0)),
            statics: None,
            static_generation: None,
            bodies: None,
            targets: None,
            drawn: DrawnInputs::default(),
        }
    }

    /// Offscreen images of `size_px` (kept while the size stays the same).
    fn targets(&self, device: &wgpu::Device, size_px: [u32; 2]) -> Targets {
        let size = wgpu::Extent3d {
            width: size_px[0],
            height: size_px[1],
            depth_or_array_layers: 1,
        };
        let texture = |label: &str, format: wgpu::TextureFormat, samples: u32, sampled: bool| {
            let mut usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
            if sampled {
                usage |= wgpu::TextureUsages::TEXTURE_BINDING;
            }
            device
                .create_texture(&wgpu::TextureDescriptor {
                    label: Some(label),
                    size,
                    mip_level_count: 1,
                    sample_count: samples,
                    dimension: wgpu::TextureDimension::D2,
                    format,
                    usage,
                    view_formats: &[],
                })
                .create_view(&wgpu::TextureViewDescriptor::default())
        };
        let samples = self.caps.msaa_samples;
        let color = texture("scene colour", SCENE_COLOR_FORMAT, 1, true); // words: a GPU debug label
        let msaa_color =
            (samples > 1).then(|| texture("scene colour msaa", SCENE_COLOR_FORMAT, samples, false)); // words: a GPU debug label
        let depth = texture("scene depth", SCENE_DEPTH_FORMAT, samples, false); // words: a GPU debug label
        let blit_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("blit"),
            layout: &self.blit_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&color),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&self.sampler),
                },
            ],
        });
        Targets {
            size_px,
            msaa_color,
            depth,
            color,
            blit_bind_group,
        }
    }

    /// Uploads one view's frame: uniforms, every animal into one instance buffer
    /// (grown to the next power of two when too small), the deformed bodies (a
    /// buffer that grows likewise), and the static mesh when its generation changed.
    fn upload(
        view: &mut ViewState,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        frame: &SceneCallback,
    ) {
        queue.write_buffer(&view.uniform_buffer, 0, bytemuck::bytes_of(&frame.uniforms));
        view.ranges = instance_ranges(frame);
        let total = view.ranges[3].1.end as usize;
        if total > view.instance_capacity {
            view.instance_capacity = total.next_power_of_two();
            view.instances = Self::instance_buffer(device, view.instance_capacity);
        }
        let mut offset = 0;
        for animals in [&frame.fish, &frame.sharks, &frame.rays] {
            if !animals.is_empty() {
                queue.write_buffer(
                    &view.instances,
                    (offset * size_of::<FishInstance>()) as u64,
                    bytemuck::cast_slice(animals.as_slice()),
                );
            }
            offset += animals.len();
        }
        if !frame.bodies.indices.is_empty() {
            view.bodies
                .get_or_insert_with(|| DynamicMesh::new(device))
                .write(device, queue, &frame.bodies);
        } else if let Some(bodies) = &mut view.bodies {
            bodies.index_count = 0;
        }
        if view.static_generation != Some(frame.statics.generation) {
            view.statics = GpuMesh::upload(device, "static scene", &frame.statics.mesh); // words: a GPU debug label
            view.static_generation = Some(frame.statics.generation);
        }
    }

    fn render_scene(&self, view: &ViewState, encoder: &mut wgpu::CommandEncoder) {
        let Some(targets) = &view.targets else {
            return;
        };
        let (color_view, resolve_target) = match &targets.msaa_color {
            Some(msaa) => (msaa, Some(&targets.color)),
            None => (&targets.color, None),
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("aquarium"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: color_view,
                depth_slice: None,
                resolve_target,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &targets.depth,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Discard,
                }),
                stencil_ops: None,
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_bind_group(0, &view.uniform_bind_group, &[]);

        pass.set_pipeline(&self.background_pipeline);
        pass.draw(0..3, 0..1);

        if let Some(statics) = &view.statics {
            pass.set_pipeline(&self.static_pipeline);
            pass.set_vertex_buffer(0, statics.vertices.slice(..));
            pass.set_index_buffer(statics.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..statics.index_count, 0, 0..1);
        }

        if let Some(bodies) = view.bodies.as_ref().filter(|b| b.index_count > 0) {
            pass.set_pipeline(&self.body_pipeline);
            pass.set_vertex_buffer(0, bodies.vertices.slice(..));
            pass.set_index_buffer(bodies.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..bodies.index_count, 0, 0..1);
        }

        let stride = size_of::<FishInstance>() as u64;
        for ((animal, range), mesh) in view.ranges.iter().zip(&self.animal_meshes) {
            let Some(mesh) = mesh else { continue };
            if range.is_empty() {
                continue;
            }
            pass.set_pipeline(match animal {
                Animal::Ray => &self.ray_pipeline,
                Animal::Fish | Animal::FarFish | Animal::Shark => &self.swim_pipeline,
            });
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            // An offset into the buffer rather than a first instance: WebGL2 has no
            // base instance.
            let bytes = u64::from(range.start) * stride..u64::from(range.end) * stride;
            pass.set_vertex_buffer(1, view.instances.slice(bytes));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..mesh.index_count, 0, 0..range.len() as u32);
        }

        pass.set_pipeline(&self.surface_pipeline);
        pass.draw(0..6, 0..1);
    }
}

impl CallbackTrait for SceneCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen_descriptor: &ScreenDescriptor,
        egui_encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(renderer) = resources.get_mut::<SceneRenderer>() else {
            return Vec::new();
        };
        let max = device.limits().max_texture_dimension_2d;
        let size_px = [self.size_px[0].clamp(1, max), self.size_px[1].clamp(1, max)];
        // The view's state is taken out of the cache while it is used, so that the
        // renderer's shared parts can be borrowed alongside it.
        let mut views = std::mem::take(&mut renderer.views);
        let view = views.draw(self.view_id, || renderer.new_view(device));
        if view.targets.as_ref().is_none_or(|t| t.size_px != size_px) {
            view.targets = Some(renderer.targets(device, size_px));
            view.drawn.forget();
        }
        if !view.drawn.same_as_last(self) {
            SceneRenderer::upload(view, device, queue, self);
            renderer.render_scene(view, egui_encoder);
        }
        renderer.views = views;
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        render_pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(renderer) = resources.get::<SceneRenderer>() else {
            return;
        };
        let Some(targets) = renderer
            .views
            .get(self.view_id)
            .and_then(|view| view.targets.as_ref())
        else {
            return;
        };
        render_pass.set_pipeline(&renderer.blit_pipeline);
        render_pass.set_bind_group(0, &targets.blit_bind_group, &[]);
        render_pass.draw(0..3, 0..1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kept(cache: &ViewCache<u32>) -> Vec<u32> {
        let mut ids: Vec<u32> = cache.view_ids().collect();
        ids.sort_unstable();
        ids
    }

    #[test]
    fn views_drawn_every_frame_keep_their_own_state() {
        let mut cache = ViewCache::default();
        for frame in 0..1_000_u32 {
            for view_id in [0, 1] {
                let state = cache.draw(view_id, || 0_u32);
                *state += 1;
                assert_eq!(*state, frame + 1, "view {view_id} was rebuilt");
            }
        }
        assert_eq!(cache.get(0), Some(&1_000));
        assert_eq!(cache.get(1), Some(&1_000));
        assert_eq!(cache.get(2), None);
    }

    #[test]
    fn a_view_not_drawn_for_300_frames_is_dropped() {
        let mut cache = ViewCache::default();
        cache.draw(0, || 0_u32);
        cache.draw(1, || 0_u32);
        // Compare mode ends: only view 0 is drawn from now on.
        for _ in 0..ViewCache::<u32>::STALE_AFTER_FRAMES {
            cache.draw(0, || 0);
        }
        assert_eq!(kept(&cache), vec![0, 1], "still within the grace period");
        cache.draw(0, || 0);
        assert_eq!(kept(&cache), vec![0]);
    }

    #[test]
    fn beyond_four_views_the_least_recently_drawn_goes_but_never_one_of_this_frame() {
        let mut cache = ViewCache::default();
        // Frame 1: views 0 to 3; frame 2: views 1 to 3; frame 3: view 4 is new.
        for view_id in 0..4 {
            cache.draw(view_id, || view_id);
        }
        for view_id in 1..4 {
            cache.draw(view_id, || view_id);
        }
        cache.draw(1, || 1);
        cache.draw(4, || 4);
        assert_eq!(
            kept(&cache),
            vec![1, 2, 3, 4],
            "view 0 was drawn longest ago"
        );
        // Six views in one frame: all kept until their paint has run.
        for view_id in 10..16 {
            cache.draw(view_id, || view_id);
        }
        for view_id in 10..16 {
            assert_eq!(cache.get(view_id), Some(&view_id));
        }
        // The next frame draws only 10 and 11: others go as new views come.
        cache.draw(10, || 10);
        cache.draw(11, || 11);
        cache.draw(20, || 20);
        assert!(kept(&cache).len() <= 6);
        assert!(cache.get(10).is_some() && cache.get(11).is_some() && cache.get(20).is_some());
    }

    fn frame(fish_x: f32, eye_x: f32) -> SceneCallback {
        let fish = FishInstance {
            position_m: [fish_x, 1.0, 2.0],
            ..FishInstance::zeroed()
        };
        SceneCallback {
            view_id: 0,
            uniforms: SceneUniforms::new(
                Mat4::IDENTITY,
                Vec3::new(eye_x, 1.0, 8.0),
                Vec3::ZERO,
                Vec3::splat(4.0),
                3.0,
            ),
            fish: Arc::new(vec![fish; 3]),
            fish_detailed: 3,
            sharks: Arc::new(Vec::new()),
            rays: Arc::new(Vec::new()),
            statics: StaticScene {
                generation: 7,
                mesh: Arc::new(Mesh::default()),
            },
            bodies: Arc::new(Mesh::default()),
            size_px: [640, 360],
        }
    }

    #[test]
    fn a_frame_like_the_last_is_not_drawn_again_and_any_change_is() {
        let mut drawn = DrawnInputs::default();
        assert!(
            !drawn.same_as_last(&frame(1.0, 0.0)),
            "the first frame is drawn"
        );
        assert!(drawn.same_as_last(&frame(1.0, 0.0)), "paused, camera still");
        assert!(!drawn.same_as_last(&frame(1.001, 0.0)), "a fish moved");
        assert!(drawn.same_as_last(&frame(1.001, 0.0)));
        assert!(!drawn.same_as_last(&frame(1.001, 0.5)), "the camera moved");
        let mut fewer = frame(1.001, 0.5);
        Arc::make_mut(&mut fewer.fish).pop();
        fewer.fish_detailed = 2;
        assert!(!drawn.same_as_last(&fewer), "a fish fewer");
        let mut rebuilt = frame(1.001, 0.5);
        rebuilt.statics.generation = 8;
        assert!(!drawn.same_as_last(&rebuilt), "a rock added");
        drawn.forget();
        assert!(!drawn.same_as_last(&rebuilt), "new targets: drawn again");
    }

    #[test]
    fn a_running_tank_is_drawn_every_frame_without_copying_its_bodies() {
        let mut drawn = DrawnInputs::default();
        let running = |k: u8| {
            // Simulated time (in the uniforms) moves every frame.
            let mut f = frame(1.0 + f32::from(k) * 0.01, 0.0);
            f.uniforms.eye_m[3] = f32::from(k) * 0.1;
            f
        };
        for k in 0..10 {
            assert!(!drawn.same_as_last(&running(k)));
            if k > 0 {
                assert!(
                    !drawn.content_valid,
                    "frame {k}: nothing copied while running"
                );
            }
        }
        // Paused at the last frame: drawn once more, then only shown.
        let still = running(9);
        assert!(!drawn.same_as_last(&still));
        assert!(drawn.same_as_last(&still));
        assert!(drawn.same_as_last(&still));
    }

    /// The scene shader parses and validates (naga, as wgpu does natively) and has
    /// every entry point the pipelines name.
    #[cfg(not(target_arch = "wasm32"))]
    #[test]
    fn scene_shader_is_valid_wgsl() {
        use wgpu::naga;
        let module = naga::front::wgsl::parse_str(SCENE_SHADER)
            .unwrap_or_else(|e| panic!("{}", e.emit_to_string(SCENE_SHADER)));
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        )
        .validate(&module)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(SCENE_SHADER)));
        for name in ["vs_static", "vs_body", "vs_fish", "vs_ray", "fs_lit"] {
            assert!(
                module.entry_points.iter().any(|e| e.name == name),
                "no entry point {name}"
            );
        }
    }

    #[test]
    fn animals_share_one_instance_buffer_in_kind_order() {
        let one = FishInstance::zeroed();
        let frame = SceneCallback {
            view_id: 0,
            uniforms: SceneUniforms::zeroed(),
            fish: Arc::new(vec![one; 10]),
            fish_detailed: 4,
            sharks: Arc::new(vec![one; 2]),
            rays: Arc::new(vec![one; 3]),
            statics: StaticScene {
                generation: 0,
                mesh: Arc::new(Mesh::default()),
            },
            bodies: Arc::new(Mesh::default()),
            size_px: [1, 1],
        };
        assert_eq!(
            instance_ranges(&frame),
            [
                (Animal::Fish, 0..4),
                (Animal::FarFish, 4..10),
                (Animal::Shark, 10..12),
                (Animal::Ray, 12..15),
            ]
        );
    }
}
