#version 460
// One level of one directional mip chain (Crassin et al. 2011, section 4.1, "anisotropic
// voxels"). For rays travelling along +x, say, each pair of children along x is composited front
// to back (the nearer child occludes the farther one), and the four pairs are averaged. A wall
// across a texel then stays opaque for rays crossing it, where a plain average would make it
// 1/size opaque and let wide cones see through thin walls.
//
// The first level (built from the grid's level 0) is one-sided: a surface voxel is opaque, and
// shows its light, only to rays that meet its front. Seen from behind or edge on it is empty, so a
// cone leaving a surface neither stops in that surface's own voxels (self-occlusion) nor gathers
// their light (self-illumination), and a lone lit plane gets no indirect light from itself.
// Voxels whose triangles disagree (the two faces of a thin wall, small features) have a short mean
// normal and stay opaque both ways.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(set = 0, binding = 0, rgba16f) uniform readonly image3D finer;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image3D coarser;
// The scene voxels' mean normals (not renormalized), read when `finer` is the grid's level 0.
layout(set = 0, binding = 2, rgba16f) uniform readonly image3D sceneNormal;
layout(push_constant) uniform Push {
    uint direction;  // 0..5 = +x, −x, +y, −y, +z, −z: the direction rays travel through this volume
    uint finerIsSceneLevel;
};

// A mean normal shorter than this (two faces of a thin wall cancel) has no side.
const float MIN_SIDED_NORMAL = 0.25f;
// Front facing: the ray meets the surface at more than ~6° from edge on.
const float FRONT_FACING = -0.1f;
// A texel this opaque hides what lies behind it.
const float OPAQUE = 0.99f;

vec4 seenAlong(ivec3 voxel, vec3 rayDirection) {
    vec4 value = imageLoad(finer, voxel);
    if (finerIsSceneLevel == 0u || value.a <= 0.0f) return value;
    vec3 normal = imageLoad(sceneNormal, voxel).xyz;
    float normalLength = length(normal);
    if (normalLength < MIN_SIDED_NORMAL) return value;
    return dot(normal, rayDirection) < -FRONT_FACING * normalLength ? value : vec4(0.0f);
}

// The texel's value for rays travelling along `along` (× sign): each pair of children along the
// axis composited front to back, the four pairs averaged.
vec4 composite(ivec3 texel, int axis, bool positive, ivec3 along, vec3 rayDirection) {
    vec4 sum = vec4(0.0f);
    for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
            ivec3 across = ivec3(0);
            across[(axis + 1) % 3] = a;
            across[(axis + 2) % 3] = b;
            ivec3 first = texel * 2 + across;
            vec4 low = seenAlong(first, rayDirection);
            vec4 high = seenAlong(first + along, rayDirection);
            vec4 near = positive ? low : high;
            vec4 far = positive ? high : low;
            sum += near + (1.0f - near.a) * far;  // premultiplied front-to-back "over"
        }
    }
    return sum * 0.25f;
}

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    ivec3 size = imageSize(coarser);
    if (any(greaterThanEqual(texel, size))) return;
    int axis = int(direction / 2u);
    bool positive = (direction & 1u) == 0u;
    ivec3 along = ivec3(0);
    along[axis] = 1;
    vec3 rayDirection = vec3(along) * (positive ? 1.0f : -1.0f);
    vec4 value = composite(texel, axis, positive, along, rayDirection);
    // What lies behind an opaque texel, seen along the ray, is unreachable: it is stored as
    // opaque too. Otherwise trilinear filtering blends a wall's texel with the empty one behind
    // it, no sample of a wide cone sees the wall's full opacity, and a cone that reaches a wall
    // goes on through it (a closed emitting box gave 0.68-0.84 of its radiance, by step size).
    ivec3 before = texel - along * (positive ? 1 : -1);
    if (all(greaterThanEqual(before, ivec3(0))) && all(lessThan(before, size))) {
        vec4 front = composite(before, axis, positive, along, rayDirection);
        if (front.a >= OPAQUE) value += (1.0f - value.a) * front;
    }
    imageStore(coarser, texel, value);
}
