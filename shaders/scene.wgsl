// The aquarium: background (room + water volume), static meshes, deformed bodies
// (physical fish skinned on the CPU, `vs_body`), instanced animals (fish and sharks
// swim with `vs_fish`, stingrays with `vs_ray`) and the water surface. Lighting is computed in linear RGB; the output is gamma-encoded
// because the scene image is a plain Rgba8Unorm texture (see render_tier.rs).

struct Scene {
    world_to_clip: mat4x4<f32>,
    clip_to_world: mat4x4<f32>,
    eye: vec4<f32>,       // xyz camera position (m), w animation time (s)
    tank_min: vec4<f32>,  // xyz lower tank corner (m), w fog density (1/m)
    tank_max: vec4<f32>,  // xyz upper tank corner (m)
    sun_dir: vec4<f32>,   // xyz unit vector towards the light
};

@group(0) @binding(0) var<uniform> scene: Scene;

// Materials (mesh.rs `Material`).
const PLAIN: u32 = 0u;
const SAND: u32 = 1u;
const FRAME: u32 = 2u;
const FISH_BODY: u32 = 3u;
const FISH_FIN: u32 = 4u;
const FISH_EYE: u32 = 5u;
const SHARK_SKIN: u32 = 6u;
const RAY_BACK: u32 = 7u;
const RAY_BELLY: u32 = 8u;
const SKIN_FISH: u32 = 9u;
const SKIN_FIN: u32 = 10u;
const SKIN_SHARK: u32 = 11u;
const SKIN_SHARK_FIN: u32 = 12u;

// The material word of a vertex: the material in bits 0-4, a highlight level 0-7
// in bits 5-7 (deformed bodies only), and for deformed bodies the skin coordinates
// in bits 8-31 (body_skin.rs: `SKIN_LOCAL_MIN`, `SKIN_LOCAL_MAX`, `MATERIAL_MASK`).
const MATERIAL_MASK: u32 = 31u;
const SKIN_LOCAL_MIN: vec3<f32> = vec3<f32>(-0.65, -0.4, -0.4);
const SKIN_LOCAL_MAX: vec3<f32> = vec3<f32>(0.6, 0.4, 0.4);
// Undersides of shark fins (body_skin.rs `SHARK_BELLY_RGB`).
const SHARK_BELLY: vec3<f32> = vec3<f32>(0.80, 0.81, 0.80);

const TAU: f32 = 6.2831853;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) material: u32,
    @location(2) normal: vec3<f32>,
    @location(3) color: vec4<f32>,
};

// One animal (fish, shark or stingray): `FishInstance` in scene_renderer.rs.
struct FishIn {
    @location(4) position_length: vec4<f32>,  // xyz position (m), w body length (m)
    @location(5) forward_phase: vec4<f32>,    // xyz unit forward, w tail/wing phase (rad)
    @location(6) color: vec4<f32>,            // rgb body colour, a pattern strength
};

struct Varyings {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    // Position in the animal's mesh before animation (body lengths; x forward, y up);
    // zero for static meshes; for deformed bodies their skin coordinates (snout at
    // x = 0.5, tail-fin nodes at -0.5, y up). Patterns are painted in this frame so
    // they stay on the skin as the body bends.
    @location(3) local: vec3<f32>,
    // Material word, bits 0-7 (material and highlight level).
    @location(4) @interpolate(flat) material: u32,
};

// ---------------------------------------------------------------- water optics

fn time() -> f32 {
    return scene.eye.w;
}

// Entry and exit distances of a ray through the tank box (exit < entry: a miss).
fn tank_span(origin: vec3<f32>, dir: vec3<f32>) -> vec2<f32> {
    let inv = 1.0 / select(dir, vec3<f32>(1e-6), abs(dir) < vec3<f32>(1e-6));
    let t0 = (scene.tank_min.xyz - origin) * inv;
    let t1 = (scene.tank_max.xyz - origin) * inv;
    let near = min(t0, t1);
    let far = max(t0, t1);
    return vec2<f32>(max(max(max(near.x, near.y), near.z), 0.0), min(min(far.x, far.y), far.z));
}

// Colour of the water itself: brighter and greener near the surface.
fn water_color(y: f32) -> vec3<f32> {
    let depth = clamp((scene.tank_max.y - y) / (scene.tank_max.y - scene.tank_min.y), 0.0, 1.0);
    let shallow = vec3<f32>(0.10, 0.42, 0.52);
    let deep = vec3<f32>(0.015, 0.11, 0.22);
    return mix(shallow, deep, pow(depth, 0.8));
}

// Light lost and scattered on the way from a point to the eye through the water.
fn fog(color: vec3<f32>, point: vec3<f32>) -> vec3<f32> {
    let to_point = point - scene.eye.xyz;
    let dist = length(to_point);
    let span = tank_span(scene.eye.xyz, to_point / max(dist, 1e-4));
    let path = max(min(dist, span.y) - span.x, 0.0);
    let amount = 1.0 - exp(-path * scene.tank_min.w);
    return mix(color, water_color(point.y), amount);
}

// Caustics: bright, moving webs of light focused by the rippled surface. A warped
// grid of sine lines; two layers drifting apart give the shimmer.
fn caustic_layer(p: vec2<f32>, t: f32) -> f32 {
    var q = p;
    q += 0.45 * vec2<f32>(sin(q.y * 1.9 + t * 0.8), cos(q.x * 1.6 - t * 0.7));
    q += 0.30 * vec2<f32>(sin(q.y * 3.1 - t * 1.1), cos(q.x * 2.7 + t * 0.9));
    let lines = pow(1.0 - abs(sin(q.x * 2.2)), 7.0) + pow(1.0 - abs(sin(q.y * 2.2)), 7.0);
    return lines;
}

fn caustics(world: vec3<f32>) -> f32 {
    let t = time();
    let p = world.xz * 1.1;
    let c = caustic_layer(p, t) * caustic_layer(p * 0.83 + vec2<f32>(3.1, 1.7), t * 1.13 + 2.0);
    // Sharper near the surface, spread out deeper down.
    let depth = clamp((scene.tank_max.y - world.y) / (scene.tank_max.y - scene.tank_min.y), 0.0, 1.0);
    return c * mix(1.3, 0.7, depth);
}

fn hash2(p: vec2<f32>) -> f32 {
    return fract(sin(dot(p, vec2<f32>(127.1, 311.7))) * 43758.5453);
}

fn to_gamma(linear: vec3<f32>) -> vec4<f32> {
    return vec4<f32>(pow(max(linear, vec3<f32>(0.0)), vec3<f32>(1.0 / 2.2)), 1.0);
}

// ---------------------------------------------------------------- background

struct BackgroundOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) ndc: vec2<f32>,
};

@vertex
fn vs_background(@builtin(vertex_index) index: u32) -> BackgroundOut {
    let xy = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u)) * 2.0 - 1.0;
    var out: BackgroundOut;
    out.clip = vec4<f32>(xy, 1.0, 1.0);
    out.ndc = xy;
    return out;
}

@fragment
fn fs_background(in: BackgroundOut) -> @location(0) vec4<f32> {
    let far = scene.clip_to_world * vec4<f32>(in.ndc, 1.0, 1.0);
    let dir = normalize(far.xyz / far.w - scene.eye.xyz);
    // The classroom behind the tank: a dim, cool gradient.
    let room = mix(vec3<f32>(0.035, 0.04, 0.05), vec3<f32>(0.11, 0.13, 0.16), clamp(dir.y * 0.8 + 0.5, 0.0, 1.0));
    let span = tank_span(scene.eye.xyz, dir);
    if (span.y <= span.x) {
        return to_gamma(room);
    }
    // Looking through the water to the back glass: the water's own colour, plus soft
    // shafts of light from the surface.
    let back = scene.eye.xyz + dir * span.y;
    let path = span.y - span.x;
    let amount = 1.0 - exp(-path * scene.tank_min.w * 1.6);
    let shafts = 0.5 + 0.5 * sin(back.x * 1.7 + back.z * 0.9 + sin(back.x * 0.5 + time() * 0.4) * 2.0);
    let height = clamp((back.y - scene.tank_min.y) / (scene.tank_max.y - scene.tank_min.y), 0.0, 1.0);
    let water = water_color(back.y) * (1.0 + 0.25 * shafts * height);
    return to_gamma(mix(room * 0.6, water, amount));
}

// ---------------------------------------------------------------- static meshes

@vertex
fn vs_static(v: VertexIn) -> Varyings {
    var out: Varyings;
    out.world = v.position;
    out.clip = scene.world_to_clip * vec4<f32>(v.position, 1.0);
    out.normal = v.normal;
    out.color = v.color;
    out.local = vec3<f32>(0.0);
    out.material = v.material;
    return out;
}

// ---------------------------------------------------------------- deformed bodies

// Physical fish, skinned to their nodes on the CPU (body_skin.rs): world-space
// vertices; the skin coordinates come packed in the material word.
@vertex
fn vs_body(v: VertexIn) -> Varyings {
    var out: Varyings;
    out.world = v.position;
    out.clip = scene.world_to_clip * vec4<f32>(v.position, 1.0);
    out.normal = v.normal;
    out.color = v.color;
    let q = vec3<u32>(v.material >> 8u, v.material >> 16u, v.material >> 24u) & vec3<u32>(255u);
    out.local = mix(SKIN_LOCAL_MIN, SKIN_LOCAL_MAX, vec3<f32>(q) / 255.0);
    out.material = v.material & 255u;
    return out;
}

// ---------------------------------------------------------------- animals

// Places an animated mesh point `p` with normal `n` (mesh frame: body lengths, x
// forward, y up) in the world: scaled by the body length, x along the heading, y as
// close to world up as the heading allows (animals do not roll).
fn place(animal: FishIn, v: VertexIn, p: vec3<f32>, n: vec3<f32>) -> Varyings {
    let forward = animal.forward_phase.xyz;
    var side = cross(forward, vec3<f32>(0.0, 1.0, 0.0));
    if (dot(side, side) < 1e-6) {
        side = vec3<f32>(0.0, 0.0, 1.0);
    }
    side = normalize(side);
    let up = cross(side, forward);
    let scale = animal.position_length.w;
    let world = animal.position_length.xyz + scale * (forward * p.x + up * p.y + side * p.z);

    var out: Varyings;
    out.world = world;
    out.clip = scene.world_to_clip * vec4<f32>(world, 1.0);
    out.normal = normalize(forward * n.x + up * n.y + side * n.z);
    out.color = animal.color;
    out.local = v.position;
    out.material = v.material;
    return out;
}

// Fish and sharks: the tail beat, a wave running from head to tail, its amplitude
// growing towards the tail (body lengths). Carangiform swimming: the front half
// barely moves.
@vertex
fn vs_fish(v: VertexIn, fish: FishIn) -> Varyings {
    let x = v.position.x;
    let along = clamp((0.25 - x) / 1.0, 0.0, 1.0);
    let amplitude = 0.11 * along * along + 0.006;
    let wave = fish.forward_phase.w - 6.0 * (0.5 - x);
    let lateral = amplitude * sin(wave);
    let slope = amplitude * 6.0 * cos(wave) - 0.22 * along / 1.0 * sin(wave) * step(0.0, along);
    let p = v.position + vec3<f32>(0.0, 0.0, lateral);
    let n = normalize(vec3<f32>(v.normal.x - slope * v.normal.z, v.normal.y, v.normal.z));
    return place(fish, v, p, n);
}

// Stingrays (mesh.rs `stingray`): the wings ripple, a wave running from the front
// of the disc to the back (rajiform swimming, 0.8 waves per body length) whose
// height grows with the square of the distance from the midline, to ±0.07 body
// lengths at the wing tips; the instance's phase drives it. The tail behind the disc
// sways gently from side to side at half that rate.
@vertex
fn vs_ray(v: VertexIn, ray: FishIn) -> Varyings {
    let x = v.position.x;
    let z = v.position.z;
    let phase = ray.forward_phase.w;
    let half_span = 0.37;
    let span = min(abs(z) / half_span, 1.0);
    let lift_max = 0.07;
    let k = 0.8 * TAU;
    let wave = phase - k * (0.5 - x);
    let lift = lift_max * span * span * sin(wave);
    let dlift_dx = lift_max * span * span * k * cos(wave);
    let dlift_dz = lift_max * 2.0 * span / half_span * sign(z) * sin(wave);

    let behind = clamp((0.0 - x) / 0.5, 0.0, 1.0);
    let sway_amp = 0.06 * behind * behind;
    let sway_wave = 0.5 * phase - 4.0 * behind;
    let sway = sway_amp * sin(sway_wave);
    // d(behind)/dx = −2 and d(sway_wave)/d(behind) = −4.
    let dsway_dx = 8.0 * sway_amp * cos(sway_wave);

    let p = v.position + vec3<f32>(0.0, lift, sway);
    let n = normalize(vec3<f32>(
        v.normal.x - dlift_dx * v.normal.y - dsway_dx * v.normal.z,
        v.normal.y,
        v.normal.z - dlift_dz * v.normal.y,
    ));
    return place(ray, v, p, n);
}

// ---------------------------------------------------------------- shading

@fragment
fn fs_lit(in: Varyings, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    var n = normalize(in.normal);
    if (!front) {
        n = -n;
    }
    let to_eye = normalize(scene.eye.xyz - in.world);
    let sun = scene.sun_dir.xyz;
    var albedo = in.color.rgb;
    var shininess = 0.0;
    var caustic_gain = 0.55;
    // Light passing through thin fins from behind.
    var translucency = 0.0;
    let material = in.material & MATERIAL_MASK;
    let highlight = f32(in.material >> 5u) / 7.0;

    switch material {
        case SAND: {
            let ripple = sin(in.world.x * 5.0 + sin(in.world.z * 1.3) * 2.0) * 0.5 + 0.5;
            let grain = hash2(floor(in.world.xz * 90.0));
            albedo = vec3<f32>(0.66, 0.56, 0.40) * (0.84 + 0.12 * ripple + 0.1 * grain);
            caustic_gain = 0.6;
        }
        case FRAME: {
            albedo = in.color.rgb;
            shininess = 24.0;
            caustic_gain = 0.0;
        }
        case FISH_BODY: {
            // Countershading: dark back, pale belly, as real fish have.
            let back = clamp(in.local.y / 0.16, -1.0, 1.0) * 0.5 + 0.5;
            albedo = mix(in.color.rgb * 1.25 + vec3<f32>(0.15), in.color.rgb * 0.55, smoothstep(0.1, 0.9, back));
            // Vertical bars on some species.
            let bars = smoothstep(0.55, 0.75, sin(in.local.x * 38.0) * 0.5 + 0.5) * in.color.a;
            albedo = mix(albedo, albedo * 0.25, bars * step(-0.45, in.local.x) * step(in.local.x, 0.3));
            shininess = 40.0;
        }
        case FISH_FIN: {
            albedo = in.color.rgb * 0.8 + vec3<f32>(0.12);
            shininess = 8.0;
        }
        case FISH_EYE: {
            albedo = vec3<f32>(0.02);
            shininess = 90.0;
        }
        case SHARK_SKIN: {
            let l = in.local;
            // Countershading by facing: whatever faces up or sideways (back, flanks,
            // upright fins, tops of the pectorals) wears the instance colour, what
            // faces down is pale, with a soft line low on the flank.
            let dorsal = smoothstep(-0.3, -0.02, n.y);
            let belly = vec3<f32>(0.80, 0.81, 0.80);
            albedo = mix(belly, in.color.rgb, dorsal);
            // Five gill slits behind the eye.
            let gx = (l.x - 0.2) / 0.08;
            if (gx > 0.0 && gx < 1.0 && abs(l.z) > 0.03 && abs(l.y) < 0.04) {
                let slit = smoothstep(0.7, 0.95, sin(gx * 5.0 * TAU) * 0.5 + 0.5);
                albedo *= 1.0 - 0.45 * slit;
            }
            // Dusky or black fin tips (instance alpha): dorsal apex, pectoral and
            // tail tips.
            let tip = max(max(smoothstep(0.15, 0.2, l.y), smoothstep(0.17, 0.23, abs(l.z))), 1.0 - smoothstep(-0.48, -0.44, l.x));
            albedo = mix(albedo, albedo * 0.15, tip * in.color.a);
            shininess = 20.0;
        }
        case RAY_BACK: {
            let l = in.local;
            // Mottling, and spots scattered over a jittered grid (instance alpha).
            let mottle = 0.82 + 0.18 * sin(l.x * 41.0 + sin(l.z * 29.0) * 2.0) * sin(l.z * 37.0 + l.x * 11.0);
            let grid = l.xz * 18.0;
            let cell = floor(grid);
            let jitter = vec2<f32>(hash2(cell), hash2(cell + vec2<f32>(17.0, 5.0))) - 0.5;
            let d = length(fract(grid) - 0.5 - jitter * 0.5);
            let radius = 0.1 + 0.14 * hash2(cell + vec2<f32>(3.0, 11.0));
            let spot = (1.0 - smoothstep(radius * 0.6, radius, d)) * step(0.35, hash2(cell + vec2<f32>(9.0, 2.0)));
            albedo = in.color.rgb * mottle;
            // Darker along the raised body and on the tail.
            albedo *= mix(0.72, 1.0, smoothstep(0.03, 0.14, abs(l.z))) * select(1.0, 0.6, l.x < -0.02);
            albedo = mix(albedo, albedo * 0.2, spot * in.color.a * step(-0.02, l.x));
            shininess = 6.0;
        }
        case RAY_BELLY: {
            albedo = vec3<f32>(0.86, 0.82, 0.74);
            shininess = 8.0;
        }
        case SKIN_FISH: {
            // Countershading is in the vertex colour. Vertical bars (pattern
            // strength in alpha) from behind the head to the caudal peduncle.
            let l = in.local;
            let bars = smoothstep(0.55, 0.75, sin(l.x * 45.0) * 0.5 + 0.5) * in.color.a;
            let span = smoothstep(-0.33, -0.29, l.x) * (1.0 - smoothstep(0.3, 0.34, l.x));
            albedo = mix(albedo, albedo * 0.25, bars * span);
            shininess = 40.0;
        }
        case SKIN_FIN: {
            albedo = in.color.rgb * 0.8 + vec3<f32>(0.12);
            shininess = 8.0;
            translucency = 0.35;
        }
        case SKIN_SHARK: {
            // Countershading is in the vertex colour. Five gill slits behind the eye,
            // on the sides around the axis.
            let l = in.local;
            let gx = (l.x - 0.277) / 0.069;
            if (gx > 0.0 && gx < 1.0 && abs(l.z) > 0.03 && abs(l.y + 0.005) < 0.04) {
                let slit = smoothstep(0.7, 0.95, sin(gx * 5.0 * TAU) * 0.5 + 0.5);
                albedo *= 1.0 - 0.45 * slit;
            }
            shininess = 20.0;
        }
        case SKIN_SHARK_FIN: {
            let l = in.local;
            // Pale where the fin faces down (pectoral and pelvic undersides).
            albedo = mix(albedo, SHARK_BELLY, 0.85 * (1.0 - smoothstep(-0.35, 0.05, n.y)));
            // Dusky or black tips (pattern strength in alpha): the first dorsal's
            // apex, the pectoral tips, the tail's lobe tips.
            let dorsal = smoothstep(0.215, 0.25, l.y);
            let pectoral = smoothstep(0.17, 0.21, abs(l.z));
            let upper_lobe = 1.0 - smoothstep(-0.565, -0.53, l.x);
            let lower_lobe = smoothstep(0.065, 0.09, -l.y) * (1.0 - smoothstep(-0.44, -0.4, l.x));
            let tip = max(max(dorsal, pectoral), max(upper_lobe, lower_lobe));
            albedo = mix(albedo, albedo * 0.15, tip * in.color.a);
            shininess = 20.0;
            translucency = 0.1;
        }
        default: {}
    }

    let diffuse = max(dot(n, sun), 0.0);
    let sky = 0.5 + 0.5 * n.y;
    let light = 0.28 + 0.22 * sky + 0.75 * diffuse + translucency * max(-dot(n, sun), 0.0);
    let caustic = caustics(in.world) * caustic_gain * max(n.y, 0.0);
    var color = albedo * (light + caustic);
    if (shininess > 0.0) {
        let h = normalize(sun + to_eye);
        color += vec3<f32>(0.5) * pow(max(dot(n, h), 0.0), shininess) * diffuse;
    }
    if (highlight > 0.0) {
        // A selected fish: a warm tint, strongest at the rim.
        let rim = 1.0 - abs(dot(n, to_eye));
        color = mix(color, vec3<f32>(1.0, 0.86, 0.35), highlight * (0.2 + 0.7 * rim * rim));
    }
    return to_gamma(fog(color, in.world));
}

// ---------------------------------------------------------------- water surface

struct SurfaceOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_surface(@builtin(vertex_index) index: u32) -> SurfaceOut {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    let c = corners[index];
    let lo = scene.tank_min.xyz;
    let hi = scene.tank_max.xyz;
    let world = vec3<f32>(mix(lo.x, hi.x, c.x), hi.y - 0.02, mix(lo.z, hi.z, c.y));
    var out: SurfaceOut;
    out.world = world;
    out.clip = scene.world_to_clip * vec4<f32>(world, 1.0);
    return out;
}

@fragment
fn fs_surface(in: SurfaceOut) -> @location(0) vec4<f32> {
    let t = time();
    let ripple = vec2<f32>(
        sin(in.world.x * 2.3 + t * 1.3) + sin(in.world.z * 3.1 - t * 0.9) * 0.6,
        cos(in.world.z * 2.1 + t * 1.1) + cos(in.world.x * 2.9 + t * 0.7) * 0.6,
    ) * 0.06;
    let n = normalize(vec3<f32>(ripple.x, 1.0, ripple.y));
    let to_eye = normalize(scene.eye.xyz - in.world);
    let fresnel = pow(1.0 - abs(dot(n, to_eye)), 3.0);
    let h = normalize(scene.sun_dir.xyz + to_eye);
    let glint = pow(max(dot(n, h), 0.0), 120.0);
    let color = mix(vec3<f32>(0.35, 0.7, 0.8), vec3<f32>(0.9, 0.97, 1.0), fresnel) + vec3<f32>(glint);
    let alpha = clamp(0.10 + 0.45 * fresnel + glint, 0.0, 0.85);
    return vec4<f32>(pow(color, vec3<f32>(1.0 / 2.2)), alpha);
}
