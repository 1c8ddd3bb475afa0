// gaitlab's 3-D scene pass (render/gpu.rs): lit capsules and spheres from one
// instanced unit-capsule mesh, the ground with its fading grid (or the
// terrain's triangles), blob shadows and contact marks, and screen-width line
// segments.
//
// Conventions: world metres, y up; mat4x4 column-major, clip = view_proj * p
// with wgpu depth in [0, 1]. Colours come in sRGB; lighting is done in linear
// light and written back sRGB-encoded to an Rgba8Unorm target. Only vertex and
// uniform buffers (WebGL2-compatible): no storage buffers, no flat varyings.

struct Globals {
    view_proj: mat4x4<f32>,
    // xyz: eye position; w: 1 perspective, 0 orthographic.
    eye: vec4<f32>,
    // xyz: unit viewing direction; w: pixels per point.
    forward: vec4<f32>,
    // width px, height px, 1 / width, 1 / height.
    viewport: vec4<f32>,
    // ground quad centre x, z; grid fade start, fade end (metres from the eye).
    ground: vec4<f32>,
    // x: grid on (0/1); y: shadow strength; z: ground height; w: height where shadows vanish.
    flags: vec4<f32>,
    background: vec4<f32>,
    ground_color: vec4<f32>,
    grid_color: vec4<f32>,
    // xyz: unit direction toward the key light.
    light: vec4<f32>,
};

@group(0) @binding(0) var<uniform> g: Globals;

fn to_linear(c: vec3<f32>) -> vec3<f32> {
    return pow(max(c, vec3<f32>(0.0)), vec3<f32>(2.2));
}

fn to_srgb(c: vec3<f32>) -> vec3<f32> {
    return pow(clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)), vec3<f32>(1.0 / 2.2));
}

// Corner `vi` (0..6) of a quad drawn as two triangles: x in {0, 1}, y in {-1, 1}.
fn quad_corner(vi: u32) -> vec2<f32> {
    let along = f32((0x16u >> vi) & 1u);
    let side = f32((0x34u >> vi) & 1u) * 2.0 - 1.0;
    return vec2<f32>(along, side);
}

// ---------------------------------------------------------------- solids

struct SolidOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) color: vec4<f32>,
};

// Places a unit-capsule vertex (normal xyz, end w) on the capsule a -> b.
fn solid(mesh: vec4<f32>, a: vec3<f32>, b: vec3<f32>, radius: f32, color: vec4<f32>) -> SolidOut {
    let axis = b - a;
    let len = length(axis);
    var w = vec3<f32>(0.0, 1.0, 0.0);
    if len > 1e-6 {
        w = axis / len;
    }
    var helper = vec3<f32>(1.0, 0.0, 0.0);
    if abs(w.x) > 0.9 {
        helper = vec3<f32>(0.0, 0.0, 1.0);
    }
    // Right-handed frame (u, v, w): u x v = w.
    let u = normalize(cross(helper, w));
    let v = cross(w, u);
    let n = u * mesh.x + v * mesh.y + w * mesh.z;
    let world = mix(a, b, mesh.w) + n * radius;
    var out: SolidOut;
    out.clip = g.view_proj * vec4<f32>(world, 1.0);
    out.world = world;
    out.normal = n;
    out.color = color;
    return out;
}

@vertex
fn vs_capsule(
    @location(0) mesh: vec4<f32>,
    @location(1) a: vec4<f32>,
    @location(2) b: vec4<f32>,
    @location(3) color: vec4<f32>,
) -> SolidOut {
    return solid(mesh, a.xyz, b.xyz, a.w, color);
}

@fragment
fn fs_solid(in: SolidOut) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    var v = -g.forward.xyz;
    if g.eye.w > 0.5 {
        v = normalize(g.eye.xyz - in.world);
    }
    let l = g.light.xyz;
    let base = to_linear(in.color.rgb);
    let diffuse = max(dot(n, l), 0.0);
    // Hemisphere ambient: brighter facing the sky.
    let ambient = mix(0.16, 0.40, n.y * 0.5 + 0.5);
    let facing = clamp(dot(n, v), 0.0, 1.0);
    let fill = 0.20 * facing;
    let h = normalize(l + v);
    let specular = 0.25 * pow(max(dot(n, h), 0.0), 40.0) * step(0.0, dot(n, l));
    let rim = 0.30 * pow(1.0 - facing, 3.0);
    let lit = base * (ambient + 0.80 * diffuse + fill)
        + vec3<f32>(specular)
        + rim * mix(base, vec3<f32>(1.0), 0.5);
    return vec4<f32>(to_srgb(lit), 1.0);
}

// ---------------------------------------------------------------- ground

// Coverage (0..1) of grid lines `width_px` wide at integer values of `coord`.
fn line_coverage(coord: vec2<f32>, width_px: f32) -> f32 {
    let fw = max(fwidth(coord), vec2<f32>(1e-5));
    let to_line = abs(fract(coord - 0.5) - 0.5) / fw;
    let d = min(to_line.x, to_line.y);
    return 1.0 - smoothstep(0.5 * width_px - 0.5, 0.5 * width_px + 0.5, d);
}

// Screen spacing, in pixels, between integer values of `coord`.
fn spacing_px(coord: vec2<f32>) -> f32 {
    let fw = fwidth(coord);
    return 1.0 / max(max(fw.x, fw.y), 1e-5);
}

// The ground's colour at ground point p = (x, z), before distance fog: the
// ground colour with 1 m and 25 cm grid lines and the world x / z axes when the
// grid is on, the background otherwise. Lines fade out before they crowd.
fn ground_surface(p: vec2<f32>) -> vec3<f32> {
    let grid = g.flags.x;
    let base = mix(g.background.rgb, g.ground_color.rgb, grid);
    let major_spacing = spacing_px(p);
    let major = line_coverage(p, 1.5) * smoothstep(2.0, 6.0, major_spacing);
    let minor = line_coverage(p * 4.0, 1.0) * smoothstep(4.0, 12.0, spacing_px(p * 4.0)) * 0.5;
    var c = mix(base, g.grid_color.rgb, max(major, minor) * grid);
    let fw = max(fwidth(p), vec2<f32>(1e-5));
    let axis_fade = grid * smoothstep(2.0, 6.0, major_spacing) * 0.8;
    let on_x_axis = 1.0 - smoothstep(0.75, 1.75, abs(p.y) / fw.y);
    let on_z_axis = 1.0 - smoothstep(0.75, 1.75, abs(p.x) / fw.x);
    c = mix(c, vec3<f32>(0.78, 0.30, 0.28), on_x_axis * axis_fade);
    c = mix(c, vec3<f32>(0.30, 0.45, 0.85), on_z_axis * axis_fade);
    return c;
}

// How far the ground at p has faded into the background (0: not at all).
fn fog(p: vec2<f32>) -> f32 {
    let d = distance(vec3<f32>(p.x, g.flags.z, p.y), g.eye.xyz);
    return smoothstep(g.ground.z, g.ground.w, d);
}

struct GroundOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) ground: vec2<f32>,
};

@vertex
fn vs_ground(@builtin(vertex_index) vi: u32) -> GroundOut {
    let corner = quad_corner(vi);
    let p = g.ground.xy + vec2<f32>(corner.x * 2.0 - 1.0, corner.y) * g.ground.w;
    var out: GroundOut;
    out.clip = g.view_proj * vec4<f32>(p.x, g.flags.z, p.y, 1.0);
    out.ground = p;
    return out;
}

@fragment
fn fs_ground(in: GroundOut) -> @location(0) vec4<f32> {
    let surface = ground_surface(in.ground);
    return vec4<f32>(mix(surface, g.background.rgb, fog(in.ground)), 1.0);
}

// ---------------------------------------------------------------- terrain

struct TerrainOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_terrain(@location(0) position: vec4<f32>) -> TerrainOut {
    var out: TerrainOut;
    out.clip = g.view_proj * vec4<f32>(position.xyz, 1.0);
    out.world = position.xyz;
    return out;
}

// Coverage (0..1) of contour lines `width_px` wide at integer values of `h`.
fn contour_coverage(h: f32, width_px: f32) -> f32 {
    let fw = max(fwidth(h), 1e-5);
    let d = abs(fract(h - 0.5) - 0.5) / fw;
    return 1.0 - smoothstep(0.5 * width_px - 0.5, 0.5 * width_px + 0.5, d);
}

// Ground that is not flat (render/scene/terrain_mesh.rs): the floor's colour
// and grid seen from above, lit by the face's own normal (flat shading from
// the screen derivatives, so every triangle and riser shows), with a contour
// line every 5 cm of height on sloped faces. A level face reads exactly as
// the floor does.
@fragment
fn fs_terrain(in: TerrainOut) -> @location(0) vec4<f32> {
    let grid_surface = ground_surface(in.world.xz);
    let contour = contour_coverage(in.world.y * 20.0, 1.0);
    let spacing = 1.0 / max(fwidth(in.world.y * 20.0), 1e-5);
    var n = normalize(cross(dpdy(in.world), dpdx(in.world)));
    var v = -g.forward.xyz;
    if g.eye.w > 0.5 {
        v = normalize(g.eye.xyz - in.world);
    }
    if dot(n, v) < 0.0 {
        n = -n;
    }
    let level = smoothstep(0.5, 0.95, abs(n.y));
    let base = mix(g.background.rgb, g.ground_color.rgb, g.flags.x);
    var c = mix(base, grid_surface, level);
    let sloped = smoothstep(0.0005, 0.01, 1.0 - abs(n.y));
    c = mix(c, g.grid_color.rgb, contour * sloped * smoothstep(3.0, 8.0, spacing) * 0.7);
    // Lambert with a floor of ambient, scaled so that a level face keeps the floor's colour.
    let l = g.light.xyz;
    let lit = (0.5 + 0.5 * max(dot(n, l), 0.0)) / (0.5 + 0.5 * max(l.y, 0.05));
    c = c * clamp(lit, 0.5, 1.5);
    let d = distance(in.world, g.eye.xyz);
    let far = smoothstep(g.ground.z, g.ground.w, d);
    return vec4<f32>(mix(c, g.background.rgb, far), 1.0);
}

// ---------------------------------------------------------------- ground marks

struct MarkOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) ground: vec2<f32>,
    // a.xz, b.xz
    @location(1) ends: vec4<f32>,
    // radius, height, darkness, reach
    @location(2) shape: vec4<f32>,
};

@vertex
fn vs_mark(
    @builtin(vertex_index) vi: u32,
    @location(0) ends: vec4<f32>,
    @location(1) params: vec4<f32>,
) -> MarkOut {
    let a = ends.xy;
    let b = ends.zw;
    let radius = params.x;
    let height = params.y;
    // Higher casters cast wider, softer shadows.
    let reach = radius * 1.4 + height * 0.3;
    let d = b - a;
    let len = length(d);
    var dir = vec2<f32>(1.0, 0.0);
    if len > 1e-6 {
        dir = d / len;
    }
    let across = vec2<f32>(-dir.y, dir.x);
    let corner = quad_corner(vi);
    let p = mix(a - dir * reach, b + dir * reach, corner.x) + across * (corner.y * reach);
    var out: MarkOut;
    out.clip = g.view_proj * vec4<f32>(p.x, g.flags.z, p.y, 1.0);
    out.ground = p;
    out.ends = ends;
    out.shape = vec4<f32>(radius, height, params.z, reach);
    return out;
}

// Drawn with a Min blend over the ground: every mark recomputes the ground's
// colour and darkens it, so overlapping shadows never stack darker than the
// darkest one.
@fragment
fn fs_mark(in: MarkOut) -> @location(0) vec4<f32> {
    let a = in.ends.xy;
    let ba = in.ends.zw - a;
    let pa = in.ground - a;
    let t = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-12), 0.0, 1.0);
    let d = length(pa - ba * t);
    let radius = in.shape.x;
    let height = in.shape.y;
    let soft = 1.0 - smoothstep(radius * 0.25, in.shape.w, d);
    let fade = clamp(1.0 - height / g.flags.w, 0.0, 1.0);
    let alpha = clamp(in.shape.z * soft * fade * g.flags.y, 0.0, 1.0);
    let shaded = ground_surface(in.ground) * (1.0 - alpha);
    return vec4<f32>(mix(shaded, g.background.rgb, fog(in.ground)), 1.0);
}

// ---------------------------------------------------------------- lines

struct LineOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
};

// A segment as a screen-aligned quad `a.w` points wide with square caps.
@vertex
fn vs_line(
    @builtin(vertex_index) vi: u32,
    @location(0) a: vec4<f32>,
    @location(1) b: vec4<f32>,
    @location(2) color: vec4<f32>,
) -> LineOut {
    var out: LineOut;
    out.color = color;
    var ca = g.view_proj * vec4<f32>(a.xyz, 1.0);
    var cb = g.view_proj * vec4<f32>(b.xyz, 1.0);
    if ca.z < 0.0 && cb.z < 0.0 {
        // Wholly in front of the near plane: a degenerate quad draws nothing.
        out.clip = vec4<f32>(2.0, 2.0, 2.0, 1.0);
        return out;
    }
    // Clip to the near plane (clip z = 0) so both ends project sensibly.
    if ca.z < 0.0 {
        ca = mix(ca, cb, ca.z / (ca.z - cb.z));
    } else if cb.z < 0.0 {
        cb = mix(cb, ca, cb.z / (cb.z - ca.z));
    }
    let sa = ca.xy / ca.w;
    let sb = cb.xy / cb.w;
    let along_px = (sb - sa) * g.viewport.xy * 0.5;
    let len = length(along_px);
    var dir = vec2<f32>(1.0, 0.0);
    if len > 1e-4 {
        dir = along_px / len;
    }
    let across = vec2<f32>(-dir.y, dir.x);
    let corner = quad_corner(vi);
    let half_px = 0.5 * a.w * g.forward.w;
    let offset_px = across * (corner.y * half_px) + dir * ((corner.x * 2.0 - 1.0) * half_px);
    let base = mix(ca, cb, corner.x);
    out.clip = vec4<f32>(base.xy + offset_px * 2.0 * g.viewport.zw * base.w, base.z, base.w);
    return out;
}

@fragment
fn fs_line(in: LineOut) -> @location(0) vec4<f32> {
    return in.color;
}
