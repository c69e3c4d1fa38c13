// Cone tracing through the pre-filtered radiance volume (Crassin et al. 2011, section 3).
// Requires: frame (FrameConstants), voxelRadiance (sampler3D with the mip chain; rgb is
// radiance × scale premultiplied by opacity, a is opacity) and, for anisotropic voxels, the six
// directional chains directionalVoxels[AXIS_*] (their level 0 is the grid's level 1), and
// voxelNormalAt(cell), the level-0 mean normal (not renormalized) where a cone meets a surface,
// and surfacePlaneAt(uvw, lod), the surface planes (surface_planes.h) that ray visibility reads.
#ifndef VCT_CONE_TRACING_GLSL
#define VCT_CONE_TRACING_GLSL

#include "gpu_types.h"
#include "perpendicular.glsl"
#include "sky.glsl"
#include "surface_planes.h"
#include "visibility_ray.glsl"
#include "voxel_grid.h"

// Inside the grid a sample keeps the filter off the transparent border: within half a texel of a
// face (of the coarser of the levels it blends) it reads the face's texels whole. A wall lying in
// the grid's outermost texels (a room's walls, by the grid's 1/64 margin) has no texel beyond it
// to make opaque, so the border's zeros blended into it: a 40° cone from the middle of a closed
// emitting box gathered 0.93 of its radiance on average, down to 0.89, a 60° one 0.96. A sample
// outside the grid still reads the border: clamped too, it would stretch the texels of the grid's
// faces outwards, and the Cornell box's open front, closed by its walls' stretched edges, read
// 1.45x its indirect light.
vec3 clearOfTheBorder(vec3 uvw, float lod) {
    float coarserTexels = max(float(frame.grid.resolution) / exp2(floor(lod) + 1.0f), 1.0f);
    vec3 inset = vec3(0.5f / coarserTexels);
    bool inside = all(greaterThanEqual(uvw, vec3(0.0f))) && all(lessThanEqual(uvw, vec3(1.0f)));
    return inside ? clamp(uvw, inset, 1.0f - inset) : uvw;
}

// The volume seen by a cone travelling along `direction`: isotropic, or (anisotropic voxels) the
// three directional chains facing the direction. Their opacities combine as optical depths
// weighted by the direction's squared components, 1 − α = Π (1 − αᵢ)^wᵢ, so a wall that is opaque
// to rays crossing it along its normal stays opaque to every ray that crosses it obliquely (a plain
// weighted average of the αs let a 50° cone see a tenth of the way through it); each chain's
// radiance counts by its share of the optical depth.
// `blendFinest`: below level 1 the sample blends towards the finest level; a literal at each call
// (traceCone), so that a march past level 1 does not fetch that level at all.
// `chain`: where and at which level each axis's chain is read (chainReads); ChainRead(vec3(lod),
// vec3(0)) reads them all at the sample, at its level.
struct ChainRead {
    vec3 lod;    // grid levels, at most the sample's
    vec3 ahead;  // voxels along each axis, signed as the direction
};

vec4 sampleVoxels(vec3 uvw, float lod, ChainRead chain, vec3 direction, bool blendFinest) {
    uvw = clearOfTheBorder(uvw, lod);
    if ((frame.componentFlags & ANISOTROPIC_VOXELS) == 0u) return textureLod(voxelRadiance, uvw, lod);
    vec3 directionalLod = max(chain.lod - 1.0f, vec3(0.0f));
    vec3 weight = direction * direction;
    vec3 ahead = chain.ahead / float(frame.grid.resolution);
    vec3 uvwX = uvw + vec3(ahead.x, 0.0f, 0.0f), uvwY = uvw + vec3(0.0f, ahead.y, 0.0f),
         uvwZ = uvw + vec3(0.0f, 0.0f, ahead.z);
    // The chain facing the direction, by coordinate: one fetch per axis (directional_chains.h).
    vec4 alongX = textureLod(directionalVoxels[AXIS_X], vec3(uvwX.xy, directionalDepth(uvwX.z, direction.x < 0.0f)),
                             directionalLod.x);
    vec4 alongY = textureLod(directionalVoxels[AXIS_Y], vec3(uvwY.xy, directionalDepth(uvwY.z, direction.y < 0.0f)),
                             directionalLod.y);
    vec4 alongZ = textureLod(directionalVoxels[AXIS_Z], vec3(uvwZ.xy, directionalDepth(uvwZ.z, direction.z < 0.0f)),
                             directionalLod.z);
    // Optical depth of each chain; an opaque texel counts as transmitting 1/1000.
    vec3 opacity = clamp(vec3(alongX.a, alongY.a, alongZ.a), 0.0f, 0.999f);
    vec3 depth = -log(1.0f - opacity) * weight;
    float totalDepth = depth.x + depth.y + depth.z;
    vec4 directional = vec4(0.0f);
    if (totalDepth > 0.0f) {
        vec3 share = depth / totalDepth;
        vec3 radiance = share.x * (alongX.rgb / max(alongX.a, 1e-6f)) + share.y * (alongY.rgb / max(alongY.a, 1e-6f)) +
                        share.z * (alongZ.rgb / max(alongZ.a, 1e-6f));
        float alpha = 1.0f - exp(-totalDepth);
        directional = vec4(radiance * alpha, alpha);
    }
    // Below level 1 blend towards the finest (isotropic) level.
    return !blendFinest || lod >= 1.0f ? directional : mix(textureLod(voxelRadiance, uvw, 0.0f), directional, lod);
}

struct ConeResult {
    vec3 radiance;    // gathered radiance, scene units
    float occlusion;  // 0..1, with the distance falloff applied
};

// Whether a cone skips empty space through the coarse mips. A specialization constant, not a frame
// constant: lavapipe runs the test and the skip at every step even where it is off.
layout(constant_id = SKIP_EMPTY_SPACE_CONSTANT_ID) const bool SKIP_EMPTY_SPACE = true;

// Marches one cone from `origin` (world) along unit `direction`. The sample footprint grows with
// distance: diameter = 2·tan(half-aperture)·distance, sampled at mip log2(diameter) unless that
// would reach back to the cone's own surface (below). Samples are composited front to back; each
// step's opacity is corrected for the step length against the size of the texel it was filtered
// from, 1 − (1 − α)^(step / texel): a stored α is one texel's worth of opacity, so an opaque wall
// stays opaque, and a partial one as partial, at every step size.
// Self-occlusion: past a few voxels a cone's footprint (and the coarse texel it samples) reaches
// back to the surface it left, whose own voxels would then block it and lend it their light. So
// the level is kept fine enough that the sample stays SELF_CLEARANCE texels clear of that surface:
// `startHeight` is the origin's height above it (voxels), `heightRate` = dot(direction, normal).
// Probes with no surface pass a huge startHeight.
const float SELF_CLEARANCE = 1.5f;
const float NO_SURFACE = 1e9f;

// The step after `distance`, except that the cone's last step lands on `maxDistance` rather than
// beyond it. A coarse step from short of it went past it unsampled: a cone from the Cornell floor
// ended 40 voxels below the ceiling at 256³, having met neither it nor anything else.
float nextDistance(float distance, float step, float maxDistance) {
    return distance < maxDistance ? min(distance + step, maxDistance) : 2.0f * maxDistance + 1.0f;
}

// The mip level a cone samples at `distance`: its footprint's, unless that would reach back to the
// cone's own surface. Fine enough that even the next coarser level, which trilinear filtering blends
// in, stays SELF_CLEARANCE texels above that surface.
float coneSampleLod(float distance, float tanHalfAperture, float startHeight, float heightRate, float maxLod) {
    float diameter = max(1.0f, 2.0f * tanHalfAperture * distance);
    float height = startHeight + distance * heightRate;
    float clearLod = log2(max(height / SELF_CLEARANCE, 1.0f)) - 1.0f;
    return clamp(min(log2(diameter), clearLod), 0.0f, maxLod);
}

// The longest step, in texels of the finer of the two levels trilinear filtering blends.
const float MAX_STEP_TEXELS = 2.0f;

// The march's step at a sample of footprint `diameter` filtered from level `lod`: a fraction of the
// footprint, but never more than MAX_STEP_TEXELS texels of floor(lod). Where the self-clearance
// holds the level finer than the footprint, steps of the footprint's length skipped texels, so a
// one-voxel wall was met more or less fully by where the steps fell, and every wall showed the
// voxel grid as stripes (128³, 60° cones: a plaid over the Cornell box's AO and, fainter, its
// light). A probe sliding towards a wall (ConeTracing.WhatConesGatherDoesNotStripeWithTheVoxelGrid)
// measured the largest bump at 0.068 uncapped, 0.025 / 0.020 / 0.034 / 0.044 with caps of 1 / 2 /
// 3 / 4 texels; 2 costs half the extra samples of 1. Where the footprint sets the level, a
// fraction ≤ 1 of it is the shorter, and nothing changes.
float marchStep(float diameter, float lod, float stepFraction) {
    return max(min(stepFraction * diameter, MAX_STEP_TEXELS * exp2(floor(lod))), 0.25f);
}

// A cone's march so far.
struct ConeMarch {
    vec3 color;         // composited front to back, premultiplied
    float alpha;
    float occlusion;    // with the distance falloff
    vec3 lastRadiance;  // radiance (premultiplied ÷ opacity) of the last sample met
    float distance;     // from the origin, voxels
    bool leftGrid;      // its footprint left the grid (outside is transparent black)
};

// What stays the same along a cone.
struct ConeSetup {
    vec3 start;  // grid coordinates
    vec3 direction;
    float tanHalfAperture, startHeight, heightRate;
    float stepFraction, maxDistance, stopOpacity, falloff, resolution, maxLod;
    float hitDistance;  // with ray visibility, where the axis meets the first surface; else NO_HIT
};

// Short of the first surface the axis meets, a sample reads no level whose texels (of the coarser
// of the two levels trilinear filtering blends) would reach it: what lies at and behind that
// surface is the hit's to show. Without a hit (NO_HIT) the level is left as it is.
float gatedLod(float lod, float distance, float hitDistance) {
    return min(lod, max(log2(max(hitDistance - distance, 1.0f)) - 1.0f, 0.0f));
}

// With ray visibility, where and at which level each directional chain is read: no texel that
// trilinear filtering blends may reach back behind where the cone began, along that chain's axis.
// A chain's value for rays along +x is what a ray entering a texel from its −x face sees, so a
// texel behind the cone's start shows surfaces the cone never faced: the lit front of a sheet, to
// the cones of the dark room that leave its back along +x. So the level is no coarser than keeps
// the texels clear of the start (the self-clearance, per chain); and where even the finest chain
// level's texels (two voxels) would reach it, the chain is read ahead along its axis, just far
// enough, at most half a texel (the taps are then the sample's texel and the next). Read ahead
// everywhere, every face met the cones earlier: a box's faces took their cosine shares 0.106 from
// the truth, where 0.078 without. CHAIN_MARGIN: voxels behind the start a texel may reach.
const float CHAIN_MARGIN = 0.5f;
ChainRead chainReads(float lod, float distance, ConeSetup cone) {
    if ((frame.componentFlags & RAY_VISIBILITY) == 0u) return ChainRead(vec3(lod), vec3(0.0f));
    vec3 travelled = abs(cone.direction) * distance + CHAIN_MARGIN;
    vec3 level = min(vec3(lod), max(log2(max(travelled / SELF_CLEARANCE, vec3(1.0f))) - 1.0f, vec3(0.0f)));
    vec3 texel = exp2(max(level, vec3(1.0f)));
    vec3 ahead = clamp(1.5f * texel - travelled, vec3(0.0f), 0.5f * texel);
    return ChainRead(level, sign(cone.direction) * ahead);
}

// With ray visibility, whether a sample lies behind the lit surfaces in its footprint (their
// planes, surface_planes.h, weighted by their light): where they mostly agree on a side (a mean
// normal at least SIDED_AGREEMENT long; the two faces of a wall, or a block's, cancel) and the
// sample lies more than BEHIND_MARGIN voxels behind them on average. It then sees their backs,
// which hold no light, whatever the directional chains show to rays entering their texels from
// elsewhere. A margin of 0 darkened the lit room by 9 % (samples beside lit surfaces).
const float SIDED_AGREEMENT = 0.5f;
const float BEHIND_MARGIN = 0.125f;
bool behindSurfaces(vec3 uvw, float lod, vec3 position, float resolution) {
    float weight = surfacePlaneWeight(textureLod(voxelRadiance, uvw, lod).rgb);
    if (!(weight > 0.0f)) return false;
    vec4 plane = surfacePlaneAt(uvw, lod);
    vec3 meanNormal = plane.xyz / weight;
    float meanDistance = (dot(plane.xyz, fromGridCentre(position, resolution)) - plane.w) / weight;
    return length(meanNormal) >= SIDED_AGREEMENT && meanDistance < -BEHIND_MARGIN;
}

bool marching(ConeMarch march, ConeSetup cone) {
    return !march.leftGrid && march.distance <= cone.maxDistance && march.alpha < cone.stopOpacity;
}

// One step of the march: a sample composited, or a stretch of empty space skipped.
void marchOneStep(inout ConeMarch march, ConeSetup cone, bool blendFinest) {
    float distance = march.distance;
    float diameter = max(1.0f, 2.0f * cone.tanHalfAperture * distance);
    float lod = gatedLod(coneSampleLod(distance, cone.tanHalfAperture, cone.startHeight, cone.heightRate, cone.maxLod),
                         distance, cone.hitDistance);
    vec3 position = cone.start + cone.direction * distance;
    // Stop once the footprint has left the grid (outside is transparent black): a cone that
    // stopped when its centre left would skip a wall lying in the grid's last voxels.
    if (any(lessThan(position, vec3(-0.5f * diameter))) ||
        any(greaterThan(position, vec3(cone.resolution + 0.5f * diameter)))) {
        march.leftGrid = true;
        return;
    }
    vec3 uvw = position / cone.resolution;
    float stepLength = marchStep(diameter, lod, cone.stepFraction);
    // Empty space: when a level two steps coarser holds nothing here, no finer level does
    // either (its texels are averages), so the cone can skip ahead without sampling. A zero
    // from trilinear filtering vouches for the texels around the sample of the finer of the
    // two levels it blends, so for half such a texel: 2 texels of floor(lod). (Two diameters,
    // as before, overshot that where the self-clearance keeps `lod` below the diameter.) The
    // skip advances by the march's own steps, so the samples after it fall where the march's
    // would, and skipping changes nothing but the time (a skip of its own length shifted them,
    // and what a cone met by 5 %).
    if (SKIP_EMPTY_SPACE && lod + 2.0f <= cone.maxLod) {
        float coarseOpacity = textureLod(voxelRadiance, uvw, lod + 2.0f).a;
        if (coarseOpacity <= 0.0f) {
            float emptyUntil = distance + 2.0f * exp2(floor(lod));
            for (int s = 0; s < 16 && distance < emptyUntil && distance <= cone.maxDistance; ++s) {
                float skippedDiameter = max(1.0f, 2.0f * cone.tanHalfAperture * distance);
                float skippedLod = gatedLod(
                    coneSampleLod(distance, cone.tanHalfAperture, cone.startHeight, cone.heightRate, cone.maxLod),
                    distance, cone.hitDistance);
                distance = nextDistance(distance, marchStep(skippedDiameter, skippedLod, cone.stepFraction),
                                        cone.maxDistance);
            }
            march.distance = distance;
            return;
        }
    }

    // The finest level has no sides: within a voxel of the surface the ray meets, its taps would
    // read that surface's light even where the ray meets it from behind (the hit, below, decides
    // which side it shows); the directional chains do have sides.
    bool nearHit = cone.hitDistance - distance < 1.0f;
    vec4 voxel = sampleVoxels(uvw, lod, chainReads(lod, distance, cone), cone.direction, blendFinest && !nearHit);
    // Behind the planes of the texels the sample read: below level 1 it blends in the directional
    // chains, whose finest texels are level 1's. A sheet behind a cone's start lies in the chain
    // texels that run along it, outside the finer level's footprint.
    float behindLod = (frame.componentFlags & ANISOTROPIC_VOXELS) != 0u ? max(lod, 1.0f) : lod;
    if ((frame.componentFlags & RAY_VISIBILITY) != 0u && voxel.a > 0.0f &&
        behindSurfaces(uvw, behindLod, position, cone.resolution))
        voxel.rgb = vec3(0.0f);
    if (voxel.a > 0.0f) {
        float correctedAlpha = 1.0f - pow(max(1.0f - voxel.a, 0.0f), stepLength / exp2(lod));
        vec3 correctedColor = voxel.rgb * (correctedAlpha / voxel.a);
        march.color += (1.0f - march.alpha) * correctedColor;
        march.occlusion += (1.0f - march.occlusion) * correctedAlpha / (1.0f + cone.falloff * distance);
        march.alpha += (1.0f - march.alpha) * correctedAlpha;
        march.lastRadiance = voxel.rgb / voxel.a;
    }
    march.distance = nextDistance(distance, stepLength, cone.maxDistance);
}

ConeResult traceCone(vec3 origin, vec3 direction, float tanHalfAperture, float startHeight, float heightRate) {
    VoxelGridParams grid = frame.grid;
    ConeSetup cone = ConeSetup(worldToGrid(grid, origin), direction, tanHalfAperture, startHeight, heightRate,
                               frame.coneStep, frame.coneMaxDistance, frame.coneStopOpacity, frame.aoFalloff,
                               float(grid.resolution), float(grid.mipLevels - 1u), NO_HIT);
    // With ray visibility the march ends where its axis meets a surface.
    if ((frame.componentFlags & RAY_VISIBILITY) != 0u) {
        cone.hitDistance = firstSurfaceDistance(cone.start + 0.5f * direction, direction, cone.maxDistance,
                                                cone.resolution, int(cone.maxLod)) + 0.5f;
        cone.maxDistance = min(cone.maxDistance, cone.hitDistance);
    }
    // The origin is already offset from the surface.
    ConeMarch march = ConeMarch(vec3(0.0f), 0.0f, 0.0f, vec3(0.0f), 0.5f, false);
    // Near its apex a cone samples below level 1, blending in the finest level; its level only grows
    // along it where it leaves its surface (heightRate >= 0), so past level 1 the rest of the march
    // never blends it. Two loops, since lavapipe runs both sides of a choice: one loop fetched the
    // finest level at every step.
    bool levelGrows = heightRate >= 0.0f;
    int steps = 0;
    for (; steps < 512 && marching(march, cone) &&
           (!levelGrows || coneSampleLod(march.distance, tanHalfAperture, startHeight, heightRate, cone.maxLod) < 1.0f);
         ++steps)
        marchOneStep(march, cone, true);
    for (; steps < 512 && marching(march, cone); ++steps) marchOneStep(march, cone, false);
    // Stopped because it is nearly opaque: what the last few percent would have met lies behind
    // the surface it stopped in, so the remainder takes that surface's light instead of none (a
    // closed room would otherwise lose 1 - stopOpacity of every bounce).
    if (march.alpha >= cone.stopOpacity) {
        march.color += (1.0f - march.alpha) * march.lastRadiance;
        march.occlusion += (1.0f - march.occlusion) / (1.0f + cone.falloff * march.distance);
    }
    // Stopped at the surface its axis meets: the rest of the cone takes that surface's light, filtered
    // over the cone's footprint there; a surface met from behind shows its back, which holds no light.
    else if (!march.leftGrid && march.distance >= cone.hitDistance) {
        vec3 hitPoint = cone.start + direction * (cone.hitDistance + 1e-3f);
        float hitLod = clamp(log2(max(1.0f, 2.0f * tanHalfAperture * cone.hitDistance)), 0.0f, cone.maxLod);
        // Where the footprint's light lies behind the ray's last free point (a sunlit shell beside
        // the room's wall it hit), the hit is read up to four levels finer, down to its own surface.
        vec3 beforeHit = cone.start + direction * max(cone.hitDistance - 0.5f, 0.0f);
        for (int k = 0; k < 4 && hitLod > 0.0f &&
                        behindSurfaces(hitPoint / cone.resolution, hitLod, beforeHit, cone.resolution);
             ++k)
            hitLod = max(hitLod - 1.0f, 0.0f);
        vec4 hit = sampleVoxels(hitPoint / cone.resolution, hitLod, ChainRead(vec3(hitLod), vec3(0.0f)), direction, true);
        vec3 hitNormal = voxelNormalAt(ivec3(floor(hitPoint)));
        bool fromBehind = length(hitNormal) > 0.25f && dot(hitNormal, direction) > 0.1f * length(hitNormal);
        if (!fromBehind) march.color += (1.0f - march.alpha) * hit.rgb / max(hit.a, 1e-6f);
        march.occlusion += (1.0f - march.occlusion) / (1.0f + cone.falloff * march.distance);
        march.alpha = 1.0f;
    }
    ConeResult result;
    result.radiance = march.color / frame.radianceScale;
    // What the cone did not meet, having left the grid or gone its maximum distance, it meets in
    // the sky (a cone the maximum distance cuts short inside a room sees the sky through its walls:
    // the distance is a setting for open scenes).
    if (march.alpha < cone.stopOpacity) result.radiance += (1.0f - march.alpha) * skyRadiance(direction, tanHalfAperture);
    result.occlusion = clamp(march.occlusion, 0.0f, 1.0f);
    return result;
}

// With ray visibility, a cone that ended where its axis met a surface would take that surface for
// its whole footprint, which the surface's edge may cross: a wide cone is traced as five beams half
// as wide, one along its axis and four around it, each stopped by its own ray, so the part of the
// cone that passes the edge goes on. Weighted by solid angle: the central beam holds a quarter of
// the cone's, the four the rest. (A single 40° cone aimed across a box's floor and wall took the
// floor for 0.92 of it at 40° from straight down, where 0.64 is its share, and 0.03 at 50°, 0.32.)
// `beam`: ALL_BEAMS, or the one beam to trace (AXIS_BEAM, or BEAM_AROUND_AXIS at `beamAzimuth`),
// which the still frames' mean weighs (FrameConstants.diffuseBeam). `heightRate`: dot(axis, normal),
// as traceCone takes it.
ConeResult traceDiffuseCone(vec3 origin, vec3 axis, float tanHalfAperture, float startHeight, vec3 normal,
                            float heightRate, uint beam, float beamAzimuth) {
    if ((frame.componentFlags & RAY_VISIBILITY) == 0u)
        return traceCone(origin, axis, tanHalfAperture, startHeight, heightRate);
    float beamTan = 0.5f * tanHalfAperture;
    float offset = 0.6f * atan(tanHalfAperture);
    vec3 u = perpendicularTo(axis);
    vec3 v = cross(axis, u);
    if (beam == AXIS_BEAM) return traceCone(origin, axis, beamTan, startHeight, heightRate);
    if (beam == BEAM_AROUND_AXIS) {
        vec3 direction = normalize(cos(offset) * axis + sin(offset) * (cos(beamAzimuth) * u + sin(beamAzimuth) * v));
        return traceCone(origin, direction, beamTan, startHeight, max(dot(direction, normal), 0.0f));
    }
    ConeResult centre = traceCone(origin, axis, beamTan, startHeight, heightRate);
    ConeResult result = ConeResult(0.25f * centre.radiance, 0.25f * centre.occlusion);
    for (int k = 0; k < 4; ++k) {
        vec3 side = k == 0 ? u : k == 1 ? -u : k == 2 ? v : -v;
        vec3 direction = normalize(cos(offset) * axis + sin(offset) * side);
        ConeResult around = traceCone(origin, direction, beamTan, startHeight, max(dot(direction, normal), 0.0f));
        result.radiance += 0.1875f * around.radiance;
        result.occlusion += 0.1875f * around.occlusion;
    }
    return result;
}

// Indirect diffuse light: one cone along the normal and the others in a ring around it, at
// twice the half-aperture from the normal (60° for the default 60° cones), so neighbouring
// cones touch. The weights sum to 1, so a uniform surrounding radiance L gives back L and the
// irradiance is π·Σ wᵢ·Lᵢ. Returns the weighted radiance (rgb) and the weighted occlusion (a).
// `coneCount` cones of the frame's aperture and centre weight; the ring turned by `ringTurn` of the
// spacing between its cones; `beam` and `beamAzimuth` as traceDiffuseCone takes them.
vec4 traceDiffuseConeSet(vec3 origin, vec3 normal, float startHeight, uint coneCount, float ringTurn, uint beam,
                         float beamAzimuth) {
    uint count = max(coneCount, 1u);
    float tanHalf = frame.coneTanHalfAperture;
    float centreWeight = count == 1u ? 1.0f : frame.diffuseCentreWeight;
    float sideWeight = count == 1u ? 0.0f : (1.0f - centreWeight) / float(count - 1u);
    // With ray visibility each cone sees what lies along it, and the ring stands where the set
    // integrates the cosine exactly: at the cosine-weighted mean of cos θ over the rest of the
    // hemisphere, cos θ = (2/3 − w₀)/(1 − w₀) (56° for w₀ = 0.25). Without, the cones' self-clearance
    // narrows them, and the ring at twice the half-aperture measured better.
    float ringAngle = (frame.componentFlags & RAY_VISIBILITY) != 0u
                          ? acos(clamp((2.0f / 3.0f - centreWeight) / max(1.0f - centreWeight, 1e-3f), 0.0f, 1.0f))
                          : min(2.0f * atan(tanHalf), 1.4f);
    vec3 tangent = perpendicularTo(normal);
    vec3 bitangent = cross(normal, tangent);

    ConeResult centre = traceDiffuseCone(origin, normal, tanHalf, startHeight, normal, 1.0f, beam, beamAzimuth);
    vec3 radiance = centreWeight * centre.radiance;
    float occlusion = centreWeight * centre.occlusion;
    for (uint i = 1u; i < count; ++i) {
        float azimuth = 6.28318530718f * (float(i - 1u) + ringTurn) / float(count - 1u);
        vec3 around = cos(azimuth) * tangent + sin(azimuth) * bitangent;
        vec3 direction = normalize(cos(ringAngle) * normal + sin(ringAngle) * around);
        ConeResult side =
            traceDiffuseCone(origin, direction, tanHalf, startHeight, normal, dot(direction, normal), beam, beamAzimuth);
        radiance += sideWeight * side.radiance;
        occlusion += sideWeight * side.occlusion;
    }
    return vec4(radiance, occlusion);
}

// The frame's diffuse cones (frame.diffuseConeCount), the ring turned and its beams chosen as the
// frame says.
vec4 traceDiffuseCones(vec3 origin, vec3 normal, float startHeight) {
    return traceDiffuseConeSet(origin, normal, startHeight, frame.diffuseConeCount, frame.diffuseRingTurn,
                               frame.diffuseBeam, frame.diffuseBeamAzimuth);
}

// The GGX lobe as one cone: the cone that holds half of the lobe's energy. GGX puts a fraction
// tan²θh / (α² + tan²θh) of its projected area within θh of the normal, half at θh = atan α, and
// the reflection doubles the angle: tan(half-aperture) = tan 2θh = 2α / (1 − α²). Its half-width at
// half maximum (tan ≈ 1.3·α) was narrower, and the long tail it left out blurs the truth's
// reflections: cornell-metal's full relMSE 0.0506 with it, 0.0488 with this. Wider lobes are traced
// as wide as the widest cone (frame.specularConeMaxTan, 90° by default).
float specularConeTanHalfAperture(float alpha) {
    return clamp(2.0f * alpha / max(1.0f - alpha * alpha, 1e-4f), 0.02f, frame.specularConeMaxTan);
}

// Directional albedo of the GGX lobe, (A, B) with ∫f·cosθ = F0·A + B (Karis 2014, after Lazarov 2013).
vec2 environmentBrdf(float roughness, float NdotV) {
    const vec4 c0 = vec4(-1.0f, -0.0275f, -0.572f, 0.022f);
    const vec4 c1 = vec4(1.0f, 0.0425f, 1.04f, -0.04f);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28f * NdotV)) * r.x + r.y;
    return vec2(-1.04f, 1.04f) * a004 + r.zw;
}

#endif
