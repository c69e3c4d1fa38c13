#version 460
// One level of the two directional mip chains along one axis (Crassin et al. 2011, section 4.1,
// "anisotropic voxels"). For rays travelling along +x, say, each pair of children along x is
// composited front to back (the nearer child occludes the farther one), and the four pairs are
// averaged. A wall across a texel then stays opaque for rays crossing it, where a plain average
// would make it 1/size opaque and let wide cones see through thin walls.
//
// The first level (built from the grid's level 0) is one-sided: a surface voxel is opaque, and
// shows its light, only to rays that meet its front or run along it. Seen from behind it is empty,
// so a cone leaving a surface neither stops in that surface's own voxels (self-occlusion) nor
// gathers their light (self-illumination), and a lone lit plane gets no indirect light from
// itself. Edge on it stays opaque: a cone crossing a wall obliquely reads the chains of the axes
// along the wall too, and with the wall empty there (tried) it saw through, and the closed rooms
// kept 0.69 of their indirect light.
// Voxels whose triangles disagree (the two faces of a thin wall, small features) have a short mean
// normal and stay opaque both ways.
//
// Each invocation walks one line of texels along the axis and writes both directions: the eight
// children of a texel are read once for the two, and the texel before it along the ray, whose
// composite an opaque one carries forward (below), was the walk's last step. On lavapipe this is a
// quarter of the reads of one invocation per texel and direction.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "directional_chains.h"
#include "work_list.h"

layout(local_size_x = WORK_LIST_GROUP_SIZE) in;
// The axis's two chains, one level and the next coarser (directional_chains.h).
layout(set = 0, binding = FINER_LEVEL_BINDING, rgba16f) uniform readonly image3D finer;
layout(set = 0, binding = COARSER_LEVEL_BINDING, rgba16f) uniform writeonly image3D coarser;
// The scene voxels' mean normals (not renormalized), read when the finer level is the grid's level 0.
layout(set = 0, binding = VOXEL_NORMAL_BINDING, rgba16f) uniform readonly image3D sceneNormal;
// Whether the finer level is the grid's level 0 (`finer` is then that level, the same for both
// directions): a pipeline each, since lavapipe reads the normals under a branch that skips them anyway.
layout(constant_id = FINER_IS_SCENE_LEVEL_CONSTANT_ID) const bool FINER_IS_SCENE_LEVEL = false;
// Where cones leave surfaces (voxel_volumes.h): bit 0 along +axis, bit 1 along −axis; the finer
// level's flags (not read when the finer level is the scene's) and this level's.
layout(set = 0, binding = FINER_LEAVING_BINDING, r32ui) uniform readonly uimage3D finerLeaving;
layout(set = 0, binding = COARSER_LEAVING_BINDING, r32ui) uniform writeonly uimage3D coarserLeaving;
const uint LEAVING_POSITIVE = 1u;
const uint LEAVING_NEGATIVE = 2u;
layout(push_constant) uniform Push {
    uint axis;  // 0, 1, 2 = x, y, z
    // With ray visibility (cone_tracing.glsl), a surface seen from behind is opaque and black
    // rather than empty: the cones' rays keep them clear of their own surface, and a coarse texel
    // that straddles a sheet shows its dark back, not what lies beyond it (a sheet's leak into the
    // dark room 34 -> 28 %, two faces 2 voxels apart 0.66 -> 0.07 %, 64³).
    uint opaqueFromBehind;
};

// A mean normal shorter than this (two faces of a thin wall cancel) has no side.
const float MIN_SIDED_NORMAL = 0.25f;
// Seen from behind: the ray meets the surface's back at more than ~6° from edge on.
const float FRONT_FACING = -0.1f;
// A texel this opaque hides what lies behind it.
const float OPAQUE = 0.99f;

struct Seen {
    vec4 positive, negative;  // a child as rays along +axis and −axis see it
    uint leaving;             // LEAVING_* where it holds a surface that cones leave along ±axis
};

// Where the −axis chain starts along z in the finer and the coarser image.
ivec3 finerNegativeStart, coarserNegativeStart;

Seen seenFromBothSides(ivec3 voxel) {
    Seen seen = Seen(imageLoad(finer, voxel), imageLoad(finer, voxel + finerNegativeStart), 0u);
    if (!FINER_IS_SCENE_LEVEL) seen.leaving = imageLoad(finerLeaving, voxel).r;
    if (FINER_IS_SCENE_LEVEL) {
        vec3 normal = imageLoad(sceneNormal, voxel).xyz;
        float normalLength = length(normal);
        // Rays along +axis meet the front of a surface whose normal points along −axis.
        bool sided = normalLength >= MIN_SIDED_NORMAL;
        float facing = normal[axis];
        vec4 behind = vec4(0.0f, 0.0f, 0.0f, opaqueFromBehind != 0u ? seen.positive.a : 0.0f);
        if (sided && !(facing < -FRONT_FACING * normalLength)) seen.positive = behind;
        if (sided && !(-facing < -FRONT_FACING * normalLength)) seen.negative = behind;
        // Its front faces +axis: cones leave it along +axis (and rays along +axis see it from behind).
        if (sided && facing > -FRONT_FACING * normalLength) seen.leaving = LEAVING_POSITIVE;
        if (sided && -facing > -FRONT_FACING * normalLength) seen.leaving = LEAVING_NEGATIVE;
        // With ray visibility cones also leave its back: surfaces reflect on both sides, and the
        // cones leaving a sheet's back would find the texel beyond it carrying the sheet's lit
        // front (behindOpaque), opaque at their first sample: the light of one room in the next.
        // Rays that meet the front need no carried opacity: their hit ends their march there.
        if (sided && opaqueFromBehind != 0u && abs(facing) > -FRONT_FACING * normalLength)
            seen.leaving = LEAVING_POSITIVE | LEAVING_NEGATIVE;
    }
    return seen;
}

// The texel's values for rays along +axis and −axis: each pair of children along the axis
// composited front to back (premultiplied "over"), the four pairs averaged.
Seen composite(ivec3 texel, ivec3 along) {
    Seen sum = Seen(vec4(0.0f), vec4(0.0f), 0u);
    for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
            ivec3 across = ivec3(0);
            across[(axis + 1) % 3] = a;
            across[(axis + 2) % 3] = b;
            ivec3 first = texel * 2 + across;
            Seen low = seenFromBothSides(first);
            Seen high = seenFromBothSides(first + along);
            sum.positive += low.positive + (1.0f - low.positive.a) * high.positive;
            sum.negative += high.negative + (1.0f - high.negative.a) * low.negative;
            sum.leaving |= low.leaving | high.leaving;
        }
    }
    sum.positive *= 0.25f;
    sum.negative *= 0.25f;
    return sum;
}

// What lies behind an opaque texel, seen along the ray, is unreachable: it is stored as opaque too.
// Otherwise trilinear filtering blends a wall's texel with the empty one behind it, no sample of a
// wide cone sees the wall's full opacity, and a cone that reaches a wall goes on through it (a
// closed emitting box gave 0.68-0.84 of its radiance, by step size).
// Except where cones leave a surface along the ray (`leaving`, in either texel): a cone starting
// on a surface has not come through what lies behind it. Carried across the floor of a room built
// on a slab, the slab's opacity stood in front of the floor, a texel further at every level, and
// the floor's cones met it (a black floor over a dark slab in an emitting box gathered 0.76 of its
// light, 0.93 over an emitting one whose light it saw instead of the walls').
vec4 behindOpaque(vec4 value, vec4 front, bool leaving) {
    return front.a >= OPAQUE && !leaving ? value + (1.0f - value.a) * front : value;
}

void main() {
    ivec3 size = imageSize(coarser);
    size.z /= int(DIRECTIONAL_DEPTH_SIDES);
    coarserNegativeStart = ivec3(0, 0, size.z * int(DIRECTIONAL_NEGATIVE_SIDES));
    finerNegativeStart = FINER_IS_SCENE_LEVEL ? ivec3(0) : 2 * coarserNegativeStart;
    uint across1 = (axis + 1u) % 3u, across2 = (axis + 2u) % 3u;
    uint line = gl_GlobalInvocationID.x;
    if (line >= uint(size[across1] * size[across2])) return;
    ivec3 texel = ivec3(0);
    texel[across1] = int(line % uint(size[across1]));
    texel[across2] = int(line / uint(size[across1]));
    ivec3 along = ivec3(0);
    along[axis] = 1;

    // Rays along +axis meet texel i−1 before i; rays along −axis meet i+1 before i, so the −axis
    // value of a texel is written one step later, once the next composite is known.
    Seen last = composite(texel, along);
    imageStore(coarser, texel, last.positive);
    imageStore(coarserLeaving, texel, uvec4(last.leaving));
    for (int i = 1; i < size[axis]; ++i) {
        Seen current = composite(texel + along * i, along);
        uint leaving = last.leaving | current.leaving;
        imageStore(coarser, texel + along * i,
                   behindOpaque(current.positive, last.positive, (leaving & LEAVING_POSITIVE) != 0u));
        imageStore(coarser, coarserNegativeStart + texel + along * (i - 1),
                   behindOpaque(last.negative, current.negative, (leaving & LEAVING_NEGATIVE) != 0u));
        imageStore(coarserLeaving, texel + along * i, uvec4(current.leaving));
        last = current;
    }
    imageStore(coarser, coarserNegativeStart + texel + along * (size[axis] - 1), last.negative);
}
