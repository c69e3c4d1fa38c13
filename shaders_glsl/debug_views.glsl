// Views for understanding: G-buffer channels, ambient occlusion, the voxel grid itself, and which
// sun shadow map shades each surface.
// Requires the shading pass's bindings (G-buffer, voxel volumes, lights), cone_tracing.glsl and
// direct_light.glsl (its shadows).
#ifndef VCT_DEBUG_VIEWS_GLSL
#define VCT_DEBUG_VIEWS_GLSL

// Walks the camera ray through the texels of one level (Amanatides & Woo 1987) and returns the
// first occupied one: albedo, normal (mapped to 0..1) or, at level `mip`, radiance, per `view`.
// Albedo and normal show level 0. Albedo and radiance are shaded by the face the ray entered the
// texel through, so the voxels read as cubes; normals are shown as they are. (A march in steps of
// a third of a texel, filtered, found each surface at a depth set by where its steps fell, and drew
// concentric rings over every wall.)
vec3 voxelView(ivec2 pixel, uint view, float mip) {
    vec2 ndc = (vec2(pixel) + 0.5f) * frame.inverseRenderSize * 2.0f - 1.0f;
    vec4 nearPoint = frame.inverseViewProjection * vec4(ndc, 0.0f, 1.0f);
    vec4 farPoint = frame.inverseViewProjection * vec4(ndc, 1.0f, 1.0f);
    vec3 origin = worldToGrid(frame.grid, nearPoint.xyz / nearPoint.w);
    vec3 direction = normalize(worldToGrid(frame.grid, farPoint.xyz / farPoint.w) - origin);
    // No zero component: the walk divides by each.
    direction = mix(direction, vec3(1e-7f), lessThan(abs(direction), vec3(1e-7f)));
    int level = view == DEBUG_VOXEL_RADIANCE ? int(mip) : 0;
    float texel = exp2(float(level));
    int size = max(int(frame.grid.resolution) >> level, 1);
    float resolution = float(frame.grid.resolution);

    // Where the ray enters the grid's box (slab test), and through which face.
    vec3 inverse = 1.0f / direction;
    vec3 t0 = -origin * inverse;
    vec3 t1 = (vec3(resolution) - origin) * inverse;
    vec3 nearT = min(t0, t1);
    float enter = max(max(nearT.x, nearT.y), max(nearT.z, 0.0f));
    float leave = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), max(t0.z, t1.z));
    if (enter >= leave) return vec3(0.0f);
    int axis = nearT.x >= max(nearT.y, nearT.z) ? 0 : (nearT.y >= nearT.z ? 1 : 2);

    ivec3 cell = clamp(ivec3(floor((origin + direction * enter) / texel)), ivec3(0), ivec3(size - 1));
    ivec3 stepCell = ivec3(sign(direction));
    vec3 crossing = abs(texel * inverse);  // ray length across one texel, per axis
    vec3 nextT = ((vec3(cell) + step(0.0f, direction)) * texel - origin) * inverse;
    const vec3 faceShade = vec3(1.0f, 0.8f, 0.6f);  // x, y, z faces
    for (int i = 0; i < 3 * size; ++i) {
        if (view == DEBUG_VOXEL_RADIANCE) {
            vec4 radiance = texelFetch(voxelRadiance, cell, level);
            if (radiance.a > 0.0f) return faceShade[axis] * radiance.rgb / (radiance.a * frame.radianceScale);
        } else if (texelFetch(voxelAlbedo, cell, 0).a > 0.0f) {
            if (view == DEBUG_VOXEL_ALBEDO) return faceShade[axis] * texelFetch(voxelAlbedo, cell, 0).rgb;
            vec3 normal = texelFetch(voxelNormal, cell, 0).xyz;
            normal = dot(normal, normal) > 0.0f ? normalize(normal) : vec3(0.0f);
            return normal * 0.5f + 0.5f;  // data: not shaded
        }
        axis = nextT.x <= min(nextT.y, nextT.z) ? 0 : (nextT.y <= nextT.z ? 1 : 2);
        cell[axis] += stepCell[axis];
        if (cell[axis] < 0 || cell[axis] >= size) break;
        nextT[axis] += crossing[axis];
    }
    return vec3(0.0f);
}

// Which of the first sun's shadow maps shades the surface (render/sun_cascades.h): its cascades
// from the finest red, green, blue, yellow, magenta, cyan, the scene-fitted map grey; lit by the
// sun's cosine so the scene stays legible. Black without a sun.
vec3 sunCascadeView(vec3 position, vec3 normal) {
    const vec3 palette[7] = vec3[7](vec3(1.0f, 0.25f, 0.2f), vec3(0.3f, 0.9f, 0.3f), vec3(0.3f, 0.45f, 1.0f),
                                    vec3(1.0f, 0.9f, 0.2f), vec3(0.9f, 0.3f, 0.9f), vec3(0.2f, 0.9f, 0.9f),
                                    vec3(0.55f));
    for (uint i = 0u; i < frame.firstAreaLight; ++i) {
        GpuLight light = lights[i];
        if (uint(light.radiantIntensity.w) != LIGHT_DIRECTIONAL) continue;
        ShadowLookup whole = shadowLookup(light, position, normal, 1.0f);
        ShadowLookup chosen = finestCascade(light, position, normal, whole);
        uint first = uint(light.cascades.x), count = uint(light.cascades.y);
        uint index = 6u;
        for (uint c = 0u; c < min(count, 6u); ++c)
            if (shadowViews[first + c].viewProjection == chosen.view.viewProjection) index = c;
        return palette[index] * (0.35f + 0.65f * max(dot(normal, -light.direction.xyz), 0.0f));
    }
    return vec3(0.0f);
}

vec3 debugView(ivec2 pixel, vec4 positionMaterial) {
    uint view = frame.debugView;
    if (view >= DEBUG_VOXEL_ALBEDO && view <= DEBUG_VOXEL_RADIANCE)
        return voxelView(pixel, view, float(frame.debugVoxelMip));
    if (positionMaterial.w < 0.5f) return vec3(0.0f);
    vec4 normalSide = texelFetch(gNormal, pixel, 0);
    vec3 normal = normalSide.xyz;
    if (view == DEBUG_SUN_CASCADES) return sunCascadeView(positionMaterial.xyz, normal);
    if (view == DEBUG_BASE_COLOR) return texelFetch(gBaseColor, pixel, 0).rgb;
    if (view == DEBUG_NORMAL) return normal * 0.5f + 0.5f;
    if (view == DEBUG_DEPTH) {
        // Distance from the camera, 0 at the nearest point of the voxel grid's box (which holds the
        // scene) and 1 at its farthest corner, so the scene spans the whole range wherever the
        // camera is (over the grid's side, a camera outside the scene saw nearly all white).
        vec3 boxMin = frame.grid.origin;
        vec3 boxMax = boxMin + vec3(frame.grid.voxelSize * float(frame.grid.resolution));
        vec3 camera = frame.cameraPosition;
        float nearest = length(max(max(boxMin - camera, camera - boxMax), vec3(0.0f)));
        float farthest = length(max(abs(boxMin - camera), abs(boxMax - camera)));
        float distanceToCamera = length(positionMaterial.xyz - camera);
        return vec3(clamp((distanceToCamera - nearest) / max(farthest - nearest, 1e-6f), 0.0f, 1.0f));
    }
    // Ambient occlusion, 1 = open, 0 = fully occluded: the cones' times the material's occlusion
    // texture, both of which scale the indirect light.
    vec3 origin = positionMaterial.xyz + normal * (frame.coneStartOffset * frame.grid.voxelSize);
    float cones = 1.0f - traceDiffuseCones(origin, normal, frame.coneStartOffset).a;
    return vec3(cones * gbufferOcclusion(normalSide.w));
}

#endif
