// Shadow-map visibility with 5×5 percentage-closer filtering whose kernel narrows where the
// occluder is near (contact hardening).
// Requires: shadowViews[] (ShadowView), sunShadowMaps, localShadowMaps and areaShadowMaps
// (sampler2DArrayShadow), frame (FrameConstants); with SHADOW_BLOCKER_SEARCH defined, also
// sunShadowDepths, localShadowDepths and areaShadowDepths (sampler2DArray of the same maps, nearest
// filtering) for the filtered path;
// without it every lookup is one bilinear comparison.
#ifndef VCT_SHADOWS_GLSL
#define VCT_SHADOWS_GLSL

#include "perpendicular.glsl"

// The view of a point light that sees `toSurface`: cube face by the major axis, ordered
// +X, −X, +Y, −Y, +Z, −Z as the CPU builds them.
uint cubeFace(vec3 toSurface) {
    vec3 a = abs(toSurface);
    if (a.x >= a.y && a.x >= a.z) return toSurface.x >= 0.0f ? 0u : 1u;
    if (a.y >= a.z) return toSurface.y >= 0.0f ? 2u : 3u;
    return toSurface.z >= 0.0f ? 4u : 5u;
}

// How far from facing the light a receiver's plane is trusted: tan 80°.
const float MAX_RECEIVER_SLOPE = 5.67f;
// The penumbra of an occluder at distance D is D·tan(LIGHT_ANGULAR_RADIUS) wide (the sun's 0.27°,
// doubled), up to the PCF kernel: KHR_lights_punctual lights are points, whose shadows are hard,
// and a kernel as wide at contact as far away lights the crease where an occluder meets the
// receiver (a wall standing on a floor) by half.
const float TAN_LIGHT_ANGULAR_RADIUS = 0.0094f;

// A shader may compile the area lights' code out by defining AREA_LIGHTS_COMPILED false (or a
// specialization constant); by default it is in.
#ifndef AREA_LIGHTS_COMPILED
#define AREA_LIGHTS_COMPILED true
#endif
// ... and the reads of the sun's or the local lights' maps, where the scene has none of them; and
// the area lights' highlights (AREA_LIGHT_SPECULAR_COMPILED), where no material reflects specularly.
#ifndef AREA_LIGHT_SPECULAR_COMPILED
#define AREA_LIGHT_SPECULAR_COMPILED true
#endif
#ifndef SUN_SHADOWS_COMPILED
#define SUN_SHADOWS_COMPILED true
#endif
#ifndef LOCAL_SHADOWS_COMPILED
#define LOCAL_SHADOWS_COMPILED true
#endif

// ShadowView.params.x: the array a view's map is a layer of.
const uint SHADOW_ARRAY_SUN = 0u;
const uint SHADOW_ARRAY_LOCAL = 1u;
const uint SHADOW_ARRAY_AREA = 2u;

// A punctual light's map is in the sun or the local array; an area light's in the area array,
// read by its own functions. lavapipe runs both sides of a branch, texture reads and all: a lookup
// that chose among all three arrays read all three, every tap (with the light loops split by kind,
// direct_light.glsl, and area_light.h's unbranched edges: tile-room's shading 110 -> 55 ms at 128²),
// and one that chooses between two reads both unless one is compiled out (cornell-sun's shading at
// 1280×720, a sun alone: 119 -> 86 ms).
float punctualShadowMap(uint array, vec4 coordinate) {
    if (SUN_SHADOWS_COMPILED && !LOCAL_SHADOWS_COMPILED) return texture(sunShadowMaps, coordinate);
    if (LOCAL_SHADOWS_COMPILED && !SUN_SHADOWS_COMPILED) return texture(localShadowMaps, coordinate);
    if (!SUN_SHADOWS_COMPILED) return 1.0f;  // no punctual light casts shadows: never called
    return array == SHADOW_ARRAY_SUN ? texture(sunShadowMaps, coordinate) : texture(localShadowMaps, coordinate);
}

#ifdef SHADOW_BLOCKER_SEARCH
// The stored depths of the four texels around `coordinate` (uv, layer).
vec4 punctualShadowDepths(uint array, vec3 coordinate) {
    if (SUN_SHADOWS_COMPILED && !LOCAL_SHADOWS_COMPILED) return textureGather(sunShadowDepths, coordinate, 0);
    if (LOCAL_SHADOWS_COMPILED && !SUN_SHADOWS_COMPILED) return textureGather(localShadowDepths, coordinate, 0);
    if (!SUN_SHADOWS_COMPILED) return vec4(1.0f);
    return array == SHADOW_ARRAY_SUN ? textureGather(sunShadowDepths, coordinate, 0)
                                     : textureGather(localShadowDepths, coordinate, 0);
}

vec2 punctualShadowMapSize(uint array) {
    if (SUN_SHADOWS_COMPILED && !LOCAL_SHADOWS_COMPILED) return vec2(textureSize(sunShadowMaps, 0).xy);
    if (LOCAL_SHADOWS_COMPILED && !SUN_SHADOWS_COMPILED) return vec2(textureSize(localShadowMaps, 0).xy);
    return array == SHADOW_ARRAY_SUN ? vec2(textureSize(sunShadowMaps, 0).xy) : vec2(textureSize(localShadowMaps, 0).xy);
}
#endif

// The point's shadow-map coordinates: uv, and depth in the map's own [0, 1] range.
vec3 shadowMapCoordinates(ShadowView view, vec3 position) {
    vec4 clip = view.viewProjection * vec4(position, 1.0f);
    vec3 ndc = clip.xyz / clip.w;
    return vec3(ndc.xy * 0.5f + 0.5f, ndc.z);
}

#ifdef SHADOW_BLOCKER_SEARCH
// Soft shadows of an area light from its shadow cube (seen from the light's centre), in two steps.
// 1. Blocker search (as in percentage-closer soft shadows, Fernando 2005): the texels around the
//    receiver that hide part of the light give the distances of the occluders in front of it, the
//    nearest and the mean.
// 2. Visibility: rays from the receiver to AREA_SHADOW_TAPS points spread over the disc of the
//    light's area are each tested just short of where they cross those two distances, at points in
//    free space, against the cube: a ray with either point behind what the cube saw is blocked (with
//    the mean alone, a ray passed an occluder nearer than the mean, and the shadows faded as the
//    maps grew coarser and the search reached further). Unlike a filter kernel
//    centred on the receiver this knows which side of the light each ray goes to, so a box standing
//    on the floor hides the whole light from the floor at its foot (PCSS let in half), and testing
//    points off the surface, not the receiver's own plane, cannot shadow the receiver itself.
// The spiral of points turns per shadow-map texel: fine noise instead of banding.
const int AREA_SHADOW_TAPS = 16;
const float AREA_SHADOW_SEARCH_TEXELS = 48.0f;  // the widest blocker search, in texels

// For each of four texels at `tapDistance` texels from the receiver's centre, `inFront` of its plane
// (along the ray to the light), 1 if it hides part of the light from the receiver: it lies beyond
// the receiver's own surface, short of the light's own surface, and inside the cone from the
// receiver to the light, within r·Δ/(d − Δ) of it at Δ in front (a texel of slack). This keeps a
// floor from counting as an occluder for the foot of a wall that stands on it, and a surface seen
// nearly edge on from counting for itself.
vec4 hidesLight(vec4 inFront, float tapDistance, float ownSurface, float texelWorld, float distanceToLight,
                float lightRadius) {
    vec4 reach = lightRadius * inFront / max(vec4(distanceToLight) - inFront, vec4(1e-20f)) + texelWorld;
    return vec4(greaterThan(inFront, vec4(ownSurface))) * vec4(lessThan(inFront, vec4(0.95f * distanceToLight))) *
           vec4(lessThanEqual(vec4(tapDistance * texelWorld), reach));
}

// AREA_SHADOW_TAPS points on a golden-angle spiral over the unit disc, √((i + ½)/n) out at i · 137.5°
// from a first direction, walked one golden angle at a time. A constant table of the points, indexed
// in the loops, made lavapipe's tile-room shading pass (48 area lights a pixel) take 49 ms against 34
// ms walking (128², median of 3 alternated bench runs): it seemingly filled the table on every call.
const float GOLDEN_COS = -0.73736888f, GOLDEN_SIN = 0.67549029f;  // of 137.5077°
struct SpiralWalk {
    vec2 direction;  // unit: of the next point
    int index;
};

vec2 nextSpiralPoint(inout SpiralWalk walk) {
    vec2 point = walk.direction * sqrt((float(walk.index) + 0.5f) / float(AREA_SHADOW_TAPS));
    walk.direction = vec2(GOLDEN_COS * walk.direction.x - GOLDEN_SIN * walk.direction.y,
                          GOLDEN_SIN * walk.direction.x + GOLDEN_COS * walk.direction.y);
    ++walk.index;
    return point;
}

// The distance along a perspective view's axis of a depth stored in its map.
vec4 viewDepth(ShadowView view, vec4 stored) {
    float near = view.depthRange.x, far = view.depthRange.y;
    return near * far / (vec4(far) - stored * (far - near));
}

float areaLightShadow(GpuLight light, ShadowView view, vec3 position, vec3 normal, vec3 centre, vec2 depthGradient,
                      vec2 texel, float texelWorld, float distanceToLight) {
    float layer = view.params.y;
    vec3 eye = light.positionRange.xyz;
    vec3 front = light.direction.xyz;
    float discRadius = sqrt(light.direction.w / PI);
    float reachRadius = light.positionRange.w;  // every corner of the light lies within it
    // Interleaved gradient noise (Jimenez 2014) of the shadow-map texel turns the spiral.
    float turn = 6.2831853f * fract(52.9829189f * fract(dot(floor(centre.xy / texel), vec2(0.06711056f, 0.00583715f))));
    vec2 firstDirection = vec2(cos(turn), sin(turn));
    float ownSurface = 1.5f * texelWorld;
    // View depths turn into distances along the ray to the light's centre by this factor.
    float alongRay = distanceToLight / max((view.viewProjection * vec4(position, 1.0f)).w, 1e-20f);

    float searchRadius = clamp(reachRadius / texelWorld, frame.pcfRadius, AREA_SHADOW_SEARCH_TEXELS);
    float blockerDistance = 0.0f;
    float nearestBlocker = distanceToLight;
    float blockers = 0.0f;
    SpiralWalk search = SpiralWalk(firstDirection, 0);
    for (int i = 0; i < AREA_SHADOW_TAPS; ++i) {
        vec2 tap = nextSpiralPoint(search) * searchRadius;
        vec2 offset = tap * texel;
        vec3 coordinate = vec3(centre.xy + offset, layer);
        vec4 stored = textureGather(areaShadowDepths, coordinate, 0);
        float receiverDepth = viewDepth(view, vec4(centre.z + dot(depthGradient, offset))).x;
        vec4 inFront = (vec4(receiverDepth) - viewDepth(view, stored)) * alongRay;
        vec4 hides = hidesLight(inFront, length(tap), ownSurface, texelWorld, distanceToLight, reachRadius);
        blockers += dot(hides, vec4(1.0f));
        blockerDistance += dot(hides, inFront);
        vec4 nearest = mix(vec4(distanceToLight), inFront, hides);
        nearestBlocker = min(nearestBlocker, min(min(nearest.x, nearest.y), min(nearest.z, nearest.w)));
    }
    if (blockers == 0.0f) return 1.0f;
    // Each ray is tested just short of the nearest occluders and of their mean distance, where a ray
    // that meets them is still behind them from the light: occluders at several distances (a box
    // with a wall behind it) are each met where they are.
    float nearDepth = max(0.9f * nearestBlocker, ownSurface);
    float meanDepth = max(0.9f * blockerDistance / blockers, ownSurface);

    vec3 tangent = perpendicularTo(front);
    vec3 bitangent = cross(front, tangent);
    // Each ray counts by the cosine it arrives at: the part of the light below the receiver's
    // horizon, which its irradiance already leaves out, must not count as shadowed.
    float lit = 0.0f;
    float total = 0.0f;
    SpiralWalk rays = SpiralWalk(firstDirection, 0);
    for (int i = 0; i < AREA_SHADOW_TAPS; ++i) {
        vec2 onDisc = nextSpiralPoint(rays) * discRadius;
        vec3 toSample = eye + tangent * onDisc.x + bitangent * onDisc.y - position;
        float sampleDistance = length(toSample);
        float weight = max(dot(toSample, normal), 0.0f) / sampleDistance;
        vec3 near = shadowMapCoordinates(view, position + toSample * (min(nearDepth, 0.98f * sampleDistance) / sampleDistance));
        vec3 mean = shadowMapCoordinates(view, position + toSample * (min(meanDepth, 0.98f * sampleDistance) / sampleDistance));
        lit += weight * min(texture(areaShadowMaps, vec4(near.xy, layer, near.z)),
                            texture(areaShadowMaps, vec4(mean.xy, layer, mean.z)));
        total += weight;
    }
    return total > 0.0f ? lit / total : 1.0f;
}
#endif

// Where a light's shadow map sees `position`: the view (a point light's cube face by direction),
// the position pushed along the normal by a few of the map's texels (normal-offset shadows), and
// its coordinates in the map; `inMap` false where the map says nothing (behind the view, outside
// it), which is lit.
struct ShadowLookup {
    ShadowView view;
    float texelWorld;  // a texel's width at the position, world units
    vec3 offsetPosition;
    vec3 centre;  // uv, depth
    bool inMap;
};

ShadowLookup lookupInView(ShadowView view, vec3 position, vec3 normal, float distanceToLight) {
    ShadowLookup lookup;
    lookup.view = view;
    lookup.texelWorld = lookup.view.params.z * (lookup.view.params.w > 0.5f ? distanceToLight : 1.0f);
    lookup.offsetPosition = position + normal * (frame.shadowNormalOffset * lookup.texelWorld);
    vec4 clip = lookup.view.viewProjection * vec4(lookup.offsetPosition, 1.0f);
    lookup.centre = shadowMapCoordinates(lookup.view, lookup.offsetPosition);
    vec2 corner = shadowTileCorner(view);
    lookup.inMap = clip.w > 0.0f && all(greaterThanEqual(lookup.centre.xy, corner)) &&
                   all(lessThanEqual(lookup.centre.xy, corner + view.depthRange.z)) && lookup.centre.z <= 1.0f;
    return lookup;
}

ShadowLookup shadowLookup(GpuLight light, vec3 position, vec3 normal, float distanceToLight) {
    uint viewIndex = uint(light.spotShadow.z);
    if (uint(light.spotShadow.w) == 6u) viewIndex += cubeFace(position - light.positionRange.xyz);
    return lookupInView(shadowViews[viewIndex], position, normal, distanceToLight);
}

#ifdef SHADOW_BLOCKER_SEARCH
// A sun's finest cascade (render/sun_cascades.h) that holds `position` with the filter's reach
// around it, or `whole`, its scene-fitted map's lookup, where none does (a light without cascades).
// Shading only: the voxels' light keeps the scene-fitted map, which the camera does not move.
ShadowLookup finestCascade(GpuLight light, vec3 position, vec3 normal, ShadowLookup whole) {
    uint first = uint(light.cascades.x), count = uint(light.cascades.y);
    if (count == 0u) return whole;
    // The blocker search reaches pcfRadius texels out and gathers a texel around each tap.
    float reach = (frame.pcfRadius + 2.0f) / punctualShadowMapSize(SHADOW_ARRAY_SUN).x;
    for (uint i = 0u; i < count; ++i) {
        ShadowLookup lookup = lookupInView(shadowViews[first + i], position, normal, 1.0f);
        vec2 corner = shadowTileCorner(lookup.view);
        if (lookup.inMap && all(greaterThanEqual(lookup.centre.xy, corner + reach)) &&
            all(lessThanEqual(lookup.centre.xy, corner + lookup.view.depthRange.z - reach)))
            return lookup;
    }
    return whole;
}
#endif

bool castsShadows(GpuLight light) {
    return uint(light.spotShadow.w) > 0u && (frame.componentFlags & USE_SHADOWS) != 0u;
}

#ifdef SHADOW_BLOCKER_SEARCH
// The receiver plane's depth gradient over the map, dz/d(uv), from two points on the plane.
vec2 receiverDepthGradient(ShadowLookup lookup, vec3 normal) {
    vec3 tangent = perpendicularTo(normal);
    vec3 bitangent = cross(normal, tangent);
    vec3 alongTangent = shadowMapCoordinates(lookup.view, lookup.offsetPosition + tangent * lookup.texelWorld) -
                        lookup.centre;
    vec3 alongBitangent = shadowMapCoordinates(lookup.view, lookup.offsetPosition + bitangent * lookup.texelWorld) -
                          lookup.centre;
    float determinant = alongTangent.x * alongBitangent.y - alongTangent.y * alongBitangent.x;
    if (!(abs(determinant) > 1e-20f)) return vec2(0.0f);
    return vec2(alongBitangent.y * alongTangent.z - alongTangent.y * alongBitangent.z,
                alongTangent.x * alongBitangent.z - alongBitangent.x * alongTangent.z) /
           determinant;
}
#endif

// Fraction of a punctual light's view that reaches `position` (1 = lit). Each PCF tap compares
// against the depth the receiver's own plane has at that tap (receiver-plane depth bias, Isidoro
// 2006) instead of a slope-scaled bias on the occluders: an occluder seen edge on by the light (a
// wall meeting a floor) would get a bias of several texels from its own slope and let light
// through the crease where it meets the receiver.
// `filtered` = false takes one bilinear comparison instead of 25: enough for a voxel, whose
// footprint is far wider than the kernel.
float shadowVisibility(GpuLight light, vec3 position, vec3 normal, float distanceToLight, bool filtered) {
    if (!castsShadows(light)) return 1.0f;
    ShadowLookup lookup = shadowLookup(light, position, normal, distanceToLight);
#ifdef SHADOW_BLOCKER_SEARCH
    if (filtered) lookup = finestCascade(light, position, normal, lookup);
#endif
    if (!lookup.inMap) return 1.0f;
    uint array = uint(lookup.view.params.x);
    vec3 centre = lookup.centre;
#ifndef SHADOW_BLOCKER_SEARCH
    // A shader without the maps' depths (the injection) takes one comparison.
    return punctualShadowMap(array, vec4(centre.xy, lookup.view.params.y, centre.z));
#else
    if (!filtered) return punctualShadowMap(array, vec4(centre.xy, lookup.view.params.y, centre.z));
    ShadowView view = lookup.view;
    float texelWorld = lookup.texelWorld;
    vec2 texel = 1.0f / punctualShadowMapSize(array);
    vec2 depthGradient = receiverDepthGradient(lookup, normal);
    // A receiver nearly edge on to the light (whose light is nearly nothing) must not reach far:
    // its depth may change by at most MAX_RECEIVER_SLOPE × a texel's depth along the light.
    vec3 lightAxis = uint(light.radiantIntensity.w) == LIGHT_DIRECTIONAL ? light.direction.xyz
                                                                         : normalize(position - light.positionRange.xyz);
    float texelDepth = abs(shadowMapCoordinates(view, lookup.offsetPosition + lightAxis * texelWorld).z - centre.z);
    float change = length(depthGradient * texel);
    if (change > MAX_RECEIVER_SLOPE * texelDepth) depthGradient *= MAX_RECEIVER_SLOPE * texelDepth / change;
    // The normal offset keeps the centre tap clear of its own surface's texels (it lifts the point
    // 1.5 texels, more than the one texel a bilinear comparison spans at any slope); the plane
    // carries that margin to the other taps.
    float radius = frame.pcfRadius;
    // Blockers: texels of the kernel's footprint nearer the light than the receiver's plane there,
    // gathered four at a time over a 3×3 grid of taps. Their mean distance in front of the plane
    // sets the kernel's width; none means fully lit, all of them fully shadowed.
    float blockerDepth = 0.0f;
    float blockers = 0.0f;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec2 offset = vec2(x, y) * radius * texel;
            float receiverDepth = centre.z + dot(depthGradient, offset);
            vec3 coordinate = vec3(centre.xy + offset, view.params.y);
            vec4 stored = punctualShadowDepths(array, coordinate);
            vec4 nearer = vec4(lessThan(stored, vec4(receiverDepth)));
            blockers += dot(nearer, vec4(1.0f));
            blockerDepth += dot(nearer, vec4(receiverDepth) - stored);
        }
    if (blockers == 0.0f) return 1.0f;
    if (blockers == 36.0f) return 0.0f;
    float blockerDistance = blockerDepth / blockers / max(texelDepth, 1e-20f) * texelWorld;
    radius = min(radius, blockerDistance * TAN_LIGHT_ANGULAR_RADIUS / texelWorld);
    // Each tap is lit only if none of the four texels around it is nearer the light than the
    // receiver's plane there: within a texel of a crease the map holds both surfaces, and this
    // reads the floor beside a wall as shadowed rather than letting the wall's far side light it
    // (a darker line along a lit crease, against a lit line along a dark one).
    int reach = radius < 0.25f ? 0 : 2;  // at contact the 25 taps would all be the centre
    float lit = 0.0f;
    for (int y = -reach; y <= reach; ++y)
        for (int x = -reach; x <= reach; ++x) {
            vec2 offset = vec2(x, y) * (0.5f * radius) * texel;
            float depth = centre.z + dot(depthGradient, offset);
            vec3 coordinate = vec3(centre.xy + offset, view.params.y);
            vec4 stored = punctualShadowDepths(array, coordinate);
            lit += min(min(stored.x, stored.y), min(stored.z, stored.w)) >= depth ? 1.0f : 0.0f;
        }
    return lit / float((2 * reach + 1) * (2 * reach + 1));
#endif
}

// Fraction of an area light that reaches `position` (1 = lit), from its cube of shadow maps:
// unfiltered one comparison with the cube seen from the light's centre, filtered areaLightShadow.
float areaLightVisibility(GpuLight light, vec3 position, vec3 normal, float distanceToLight, bool filtered) {
    if (!castsShadows(light)) return 1.0f;
    ShadowLookup lookup = shadowLookup(light, position, normal, distanceToLight);
    if (!lookup.inMap) return 1.0f;
#ifndef SHADOW_BLOCKER_SEARCH
    return texture(areaShadowMaps, vec4(lookup.centre.xy, lookup.view.params.y, lookup.centre.z));
#else
    if (!filtered) return texture(areaShadowMaps, vec4(lookup.centre.xy, lookup.view.params.y, lookup.centre.z));
    // Its rays test points off the surface, not the plane; its blocker search needs the plane as
    // it is, the farther out the more (a slope clamped there lengthened the occluders' distance,
    // and its shadows faded as its maps grew coarser).
    vec2 texel = 1.0f / vec2(textureSize(areaShadowMaps, 0).xy);
    return areaLightShadow(light, lookup.view, lookup.offsetPosition, normal, lookup.centre,
                           receiverDepthGradient(lookup, normal), texel, lookup.texelWorld, distanceToLight);
#endif
}

#endif
