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
//! frame), instanced fish, and the translucent water surface.

use std::sync::Arc;

use bytemuck::{Pod, Zeroable};
use eframe::egui;
use eframe::egui_wgpu::{self, CallbackResources, CallbackTrait, ScreenDescriptor};
use eframe::wgpu;
use eframe::wgpu::util::DeviceExt;
use glam::{Mat4, Vec3};

use super::mesh::{self, Mesh, Vertex};
use super::render_tier::{RenderCaps, SCENE_COLOR_FORMAT, SCENE_DEPTH_FORMAT};

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

/// One fish to draw (`FishInstance` in `scene.wgsl`). 48 bytes.
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
pub struct FishInstance {
    pub position_m: [f32; 3],
    pub body_length_m: f32,
    /// Unit forward direction.
    pub forward: [f32; 3],
    /// Tail-beat phase, radians.
    pub tail_phase_rad: f32,
    /// RGB body colour; a = stripe pattern strength in [0, 1].
    pub color: [f32; 4],
}

/// The static part of the scene (floor, frame, obstacles), rebuilt when the world is.
#[derive(Clone, Debug)]
pub struct StaticScene {
    /// Changes whenever the mesh changes; the GPU copy is re-uploaded then.
    pub generation: u64,
    pub mesh: Arc<Mesh>,
}

/// Everything one frame draws. Built by the app on the CPU, consumed in `prepare`.
pub struct SceneCallback {
    pub uniforms: SceneUniforms,
    pub fish: Arc<Vec<FishInstance>>,
    pub statics: StaticScene,
    /// Size of the 3D view in physical pixels.
    pub size_px: [u32; 2],
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

/// GPU resources of the scene renderer, kept in egui-wgpu's callback resources.
pub struct SceneRenderer {
    caps: RenderCaps,
    uniform_buffer: wgpu::Buffer,
    uniform_bind_group: wgpu::BindGroup,
    background_pipeline: wgpu::RenderPipeline,
    static_pipeline: wgpu::RenderPipeline,
    fish_pipeline: wgpu::RenderPipeline,
    surface_pipeline: wgpu::RenderPipeline,
    blit_pipeline: wgpu::RenderPipeline,
    blit_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    fish_vertices: wgpu::Buffer,
    fish_indices: wgpu::Buffer,
    fish_index_count: u32,
    instances: wgpu::Buffer,
    instance_capacity: usize,
    instance_count: u32,
    static_vertices: Option<(wgpu::Buffer, wgpu::Buffer, u32)>,
    static_generation: Option<u64>,
    targets: Option<Targets>,
}

const SCENE_SHADER: &str = include_str!("../../shaders/scene.wgsl");
const BLIT_SHADER: &str = include_str!("../../shaders/blit.wgsl");

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
            label: Some("scene uniforms"),
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
        let uniform_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("scene uniforms"),
            size: size_of::<SceneUniforms>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let uniform_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene uniforms"),
            layout: &uniform_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: uniform_buffer.as_entire_binding(),
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
            "static meshes",
            "vs_static",
            "fs_lit",
            &[Some(vertex_layout.clone())],
            Some(wgpu::Face::Back),
            depth(true),
            None,
        );
        let fish_pipeline = pipeline(
            "fish",
            "vs_fish",
            "fs_lit",
            &[Some(vertex_layout), Some(instance_layout)],
            // Fins are double-sided geometry; the body is closed: back-face culling.
            Some(wgpu::Face::Back),
            depth(true),
            None,
        );
        let surface_pipeline = pipeline(
            "water surface",
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

        let fish_mesh = mesh::fish();
        let fish_vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("fish vertices"),
            contents: bytemuck::cast_slice(&fish_mesh.vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let fish_indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("fish indices"),
            contents: bytemuck::cast_slice(&fish_mesh.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        let instance_capacity = 256;
        let instances = Self::instance_buffer(device, instance_capacity);

        Self {
            caps,
            uniform_buffer,
            uniform_bind_group,
            background_pipeline,
            static_pipeline,
            fish_pipeline,
            surface_pipeline,
            blit_pipeline,
            blit_layout,
            sampler,
            fish_vertices,
            fish_indices,
            fish_index_count: fish_mesh.indices.len() as u32,
            instances,
            instance_capacity,
            instance_count: 0,
            static_vertices: None,
            static_generation: None,
            targets: None,
        }
    }

    fn instance_buffer(device: &wgpu::Device, capacity: usize) -> wgpu::Buffer {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("fish instances"),
            size: (capacity * size_of::<FishInstance>()) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        })
    }

    fn ensure_targets(&mut self, device: &wgpu::Device, size_px: [u32; 2]) {
        if self.targets.as_ref().is_some_and(|t| t.size_px == size_px) {
            return;
        }
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
        let color = texture("scene colour", SCENE_COLOR_FORMAT, 1, true);
        let msaa_color =
            (samples > 1).then(|| texture("scene colour msaa", SCENE_COLOR_FORMAT, samples, false));
        let depth = texture("scene depth", SCENE_DEPTH_FORMAT, samples, false);
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
        self.targets = Some(Targets {
            size_px,
            msaa_color,
            depth,
            color,
            blit_bind_group,
        });
    }

    fn upload(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, frame: &SceneCallback) {
        queue.write_buffer(&self.uniform_buffer, 0, bytemuck::bytes_of(&frame.uniforms));
        if frame.fish.len() > self.instance_capacity {
            self.instance_capacity = frame.fish.len().next_power_of_two();
            self.instances = Self::instance_buffer(device, self.instance_capacity);
        }
        if !frame.fish.is_empty() {
            queue.write_buffer(
                &self.instances,
                0,
                bytemuck::cast_slice(frame.fish.as_slice()),
            );
        }
        self.instance_count = frame.fish.len() as u32;
        if self.static_generation != Some(frame.statics.generation) {
            let mesh = &frame.statics.mesh;
            self.static_vertices = (!mesh.indices.is_empty()).then(|| {
                let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("static vertices"),
                    contents: bytemuck::cast_slice(&mesh.vertices),
                    usage: wgpu::BufferUsages::VERTEX,
                });
                let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("static indices"),
                    contents: bytemuck::cast_slice(&mesh.indices),
                    usage: wgpu::BufferUsages::INDEX,
                });
                (vertices, indices, mesh.indices.len() as u32)
            });
            self.static_generation = Some(frame.statics.generation);
        }
    }

    fn render_scene(&self, encoder: &mut wgpu::CommandEncoder) {
        let Some(targets) = &self.targets else {
            return;
        };
        let (view, resolve_target) = match &targets.msaa_color {
            Some(msaa) => (msaa, Some(&targets.color)),
            None => (&targets.color, None),
        };
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("aquarium"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view,
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
        pass.set_bind_group(0, &self.uniform_bind_group, &[]);

        pass.set_pipeline(&self.background_pipeline);
        pass.draw(0..3, 0..1);

        if let Some((vertices, indices, count)) = &self.static_vertices {
            pass.set_pipeline(&self.static_pipeline);
            pass.set_vertex_buffer(0, vertices.slice(..));
            pass.set_index_buffer(indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..*count, 0, 0..1);
        }

        if self.instance_count > 0 {
            pass.set_pipeline(&self.fish_pipeline);
            pass.set_vertex_buffer(0, self.fish_vertices.slice(..));
            pass.set_vertex_buffer(1, self.instances.slice(..));
            pass.set_index_buffer(self.fish_indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..self.fish_index_count, 0, 0..self.instance_count);
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
        renderer.ensure_targets(device, size_px);
        renderer.upload(device, queue, self);
        renderer.render_scene(egui_encoder);
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
        let Some(targets) = &renderer.targets else {
            return;
        };
        render_pass.set_pipeline(&renderer.blit_pipeline);
        render_pass.set_bind_group(0, &targets.blit_bind_group, &[]);
        render_pass.draw(0..3, 0..1);
    }
}
