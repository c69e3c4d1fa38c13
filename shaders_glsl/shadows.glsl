// Shadow-map visibility with 5×5 percentage-closer filtering whose kernel narrows where the
// occluder is near (contact hardening).
// Requires: shadowViews[] (ShadowView), sunShadowMaps and localShadowMaps (sampler2DArrayShadow),
// frame (FrameConstants); with SHADOW_BLOCKER_SEARCH defined, also sunShadowDepths and
// localShadowDepths (sampler2DArray of the same maps, nearest filtering) for the filtered path;
// without it every lookup is one bilinear comparison.
#ifndef VCT_SHADOWS_GLSL
#define VCT_SHADOWS_GLSL

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
const float AREA_KERNEL_SCALE = 8.0f;

float sampleShadowMap(uint array, vec4 coordinate) {
    return array == 0u ? texture(sunShadowMaps, coordinate) : texture(localShadowMaps, coordinate);
}

// The point's shadow-map coordinates: uv, and depth in the map's own [0, 1] range.
vec3 shadowMapCoordinates(ShadowView view, vec3 position) {
    vec4 clip = view.viewProjection * vec4(position, 1.0f);
    vec3 ndc = clip.xyz / clip.w;
    return vec3(ndc.xy * 0.5f + 0.5f, ndc.z);
}

// Fraction of the light's view that reaches `position` (1 = lit). The position is pushed along
// the normal by a few shadow-map texels (normal-offset shadows), and each PCF tap compares
// against the depth the receiver's own plane has at that tap (receiver-plane depth bias, Isidoro
// 2006) instead of a slope-scaled bias on the occluders: an occluder seen edge on by the light (a
// wall meeting a floor) would get a bias of several texels from its own slope and let light
// through the crease where it meets the receiver.
// `filtered` = false takes one bilinear comparison instead of 25: enough for a voxel, whose
// footprint is far wider than the kernel.
float shadowVisibility(GpuLight light, vec3 position, vec3 normal, float distanceToLight, bool filtered) {
    uint viewCount = uint(light.spotShadow.w);
    if (viewCount == 0u || (frame.componentFlags & USE_SHADOWS) == 0u) return 1.0f;
    uint viewIndex = uint(light.spotShadow.z);
    if (viewCount == 6u) viewIndex += cubeFace(position - light.positionRange.xyz);
    ShadowView view = shadowViews[viewIndex];

    float texelWorld = view.params.z * (view.params.w > 0.5f ? distanceToLight : 1.0f);
    vec3 offsetPosition = position + normal * (frame.shadowNormalOffset * texelWorld);
    vec4 clip = view.viewProjection * vec4(offsetPosition, 1.0f);
    if (clip.w <= 0.0f) return 1.0f;
    vec3 centre = shadowMapCoordinates(view, offsetPosition);
    if (any(lessThan(centre.xy, vec2(0.0f))) || any(greaterThan(centre.xy, vec2(1.0f))) || centre.z > 1.0f)
        return 1.0f;

    uint array = uint(view.params.x);
#ifndef SHADOW_BLOCKER_SEARCH
    // A shader without the maps' depths (the injection) takes one comparison.
    return sampleShadowMap(array, vec4(centre.xy, view.params.y, centre.z));
#else
    if (!filtered) return sampleShadowMap(array, vec4(centre.xy, view.params.y, centre.z));
    vec2 texel = 1.0f / vec2(array == 0u ? textureSize(sunShadowMaps, 0).xy : textureSize(localShadowMaps, 0).xy);

    // The receiver plane's depth gradient over the map, dz/d(uv), from two points on the plane.
    vec3 tangent = abs(normal.x) < 0.9f ? normalize(cross(normal, vec3(1.0f, 0.0f, 0.0f)))
                                        : normalize(cross(normal, vec3(0.0f, 1.0f, 0.0f)));
    vec3 bitangent = cross(normal, tangent);
    vec3 alongTangent = shadowMapCoordinates(view, offsetPosition + tangent * texelWorld) - centre;
    vec3 alongBitangent = shadowMapCoordinates(view, offsetPosition + bitangent * texelWorld) - centre;
    float determinant = alongTangent.x * alongBitangent.y - alongTangent.y * alongBitangent.x;
    vec2 depthGradient = vec2(0.0f);
    if (abs(determinant) > 1e-20f)
        depthGradient = vec2(alongBitangent.y * alongTangent.z - alongTangent.y * alongBitangent.z,
                             alongTangent.x * alongBitangent.z - alongBitangent.x * alongTangent.z) /
                        determinant;
    // A receiver nearly edge on to the light (whose light is nearly nothing) must not reach far:
    // its depth may change by at most MAX_RECEIVER_SLOPE × a texel's depth along the light.
    vec3 lightAxis = uint(light.radiantIntensity.w) == LIGHT_DIRECTIONAL ? light.direction.xyz
                                                                         : normalize(position - light.positionRange.xyz);
    float texelDepth = abs(shadowMapCoordinates(view, offsetPosition + lightAxis * texelWorld).z - centre.z);
    float change = length(depthGradient * texel);
    bool grazing = change > MAX_RECEIVER_SLOPE * texelDepth;
    if (grazing) depthGradient *= MAX_RECEIVER_SLOPE * texelDepth / change;
    // The normal offset keeps the centre tap clear of its own surface's texels (it lifts the point
    // 1.5 texels, more than the one texel a bilinear comparison spans at any slope); the plane
    // carries that margin to the other taps.

    // An area light's penumbra is as wide as the light seen from the occluder makes it, up to a
    // kernel AREA_KERNEL_SCALE times wider than a point light's; but not on a receiver nearly edge
    // on to the light, whose plane cannot be trusted that far (it would shadow itself).
    bool areaLight = uint(light.radiantIntensity.w) == LIGHT_AREA;
    float radius = areaLight && !grazing ? AREA_KERNEL_SCALE * frame.pcfRadius : frame.pcfRadius;
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
            vec4 stored = array == 0u ? textureGather(sunShadowDepths, coordinate, 0)
                                      : textureGather(localShadowDepths, coordinate, 0);
            vec4 nearer = vec4(lessThan(stored, vec4(receiverDepth)));
            blockers += dot(nearer, vec4(1.0f));
            blockerDepth += dot(nearer, vec4(receiverDepth) - stored);
        }
    if (blockers == 0.0f) return 1.0f;
    if (blockers == 36.0f) return 0.0f;
    float blockerDistance = blockerDepth / blockers / max(texelDepth, 1e-20f) * texelWorld;
    float tanAngularRadius = areaLight ? light.positionRange.w / max(distanceToLight - blockerDistance, 1e-20f)
                                       : TAN_LIGHT_ANGULAR_RADIUS;
    radius = min(radius, blockerDistance * tanAngularRadius / texelWorld);
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
            vec4 stored = array == 0u ? textureGather(sunShadowDepths, coordinate, 0)
                                      : textureGather(localShadowDepths, coordinate, 0);
            lit += min(min(stored.x, stored.y), min(stored.z, stored.w)) >= depth ? 1.0f : 0.0f;
        }
    return lit / float((2 * reach + 1) * (2 * reach + 1));
#endif
}

#endif
