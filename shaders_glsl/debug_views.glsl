// Views for understanding: G-buffer channels, ambient occlusion, and the voxel grid itself.
// Requires the shading pass's bindings (G-buffer, voxel volumes) and cone_tracing.glsl.
#ifndef VCT_DEBUG_VIEWS_GLSL
#define VCT_DEBUG_VIEWS_GLSL

// Marches the camera ray through the voxel volume at `mip` and returns the first voxel at
// least half opaque: albedo, normal (mapped to 0..1) or radiance, per `view`.
vec3 voxelView(ivec2 pixel, uint view, float mip) {
    vec2 ndc = (vec2(pixel) + 0.5f) * frame.inverseRenderSize * 2.0f - 1.0f;
    vec4 nearPoint = frame.inverseViewProjection * vec4(ndc, 0.0f, 1.0f);
    vec4 farPoint = frame.inverseViewProjection * vec4(ndc, 1.0f, 1.0f);
    vec3 origin = worldToGrid(frame.grid, nearPoint.xyz / nearPoint.w);
    vec3 direction = normalize(worldToGrid(frame.grid, farPoint.xyz / farPoint.w) - origin);
    float resolution = float(frame.grid.resolution.x);
    float texel = exp2(mip);
    // Start where the ray enters the grid's box (slab test), step a third of a texel.
    vec3 inverse = 1.0f / direction;
    vec3 t0 = (vec3(0.0f) - origin) * inverse;
    vec3 t1 = (vec3(resolution) - origin) * inverse;
    float enter = max(max(min(t0.x, t1.x), min(t0.y, t1.y)), max(min(t0.z, t1.z), 0.0f));
    float leave = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), max(t0.z, t1.z));
    for (float t = enter; t < leave; t += texel / 3.0f) {
        vec3 uvw = (origin + direction * t) / resolution;
        vec4 radiance = textureLod(voxelRadiance, uvw, mip);
        float opacity = view == DEBUG_VOXEL_RADIANCE ? radiance.a : textureLod(voxelAlbedo, uvw, 0.0f).a;
        if (opacity < 0.5f) continue;
        if (view == DEBUG_VOXEL_ALBEDO) return textureLod(voxelAlbedo, uvw, 0.0f).rgb;
        if (view == DEBUG_VOXEL_NORMAL) return textureLod(voxelNormal, uvw, 0.0f).xyz * 0.5f + 0.5f;
        return radiance.rgb / (radiance.a * frame.radianceScale);
    }
    return vec3(0.0f);
}

vec3 debugView(ivec2 pixel, vec4 positionMaterial) {
    uint view = frame.debugView;
    if (view >= DEBUG_VOXEL_ALBEDO) return voxelView(pixel, view, float(frame.debugVoxelMip));
    if (positionMaterial.w < 0.5f) return vec3(0.0f);
    vec3 normal = texelFetch(gNormal, pixel, 0).xyz;
    if (view == DEBUG_BASE_COLOR) return texelFetch(gBaseColor, pixel, 0).rgb;
    if (view == DEBUG_NORMAL) return normal * 0.5f + 0.5f;
    if (view == DEBUG_DEPTH) {
        // Distance from the camera, 0 at the nearest point of the voxel grid's box (which holds the
        // scene) and 1 at its farthest corner, so the scene spans the whole range wherever the
        // camera is (over the grid's side, a camera outside the scene saw nearly all white).
        vec3 boxMin = frame.grid.originVoxelSize.xyz;
        vec3 boxMax = boxMin + vec3(frame.grid.originVoxelSize.w * float(frame.grid.resolution.x));
        vec3 camera = frame.cameraPosition;
        float nearest = length(max(max(boxMin - camera, camera - boxMax), vec3(0.0f)));
        float farthest = length(max(abs(boxMin - camera), abs(boxMax - camera)));
        float distanceToCamera = length(positionMaterial.xyz - camera);
        return vec3(clamp((distanceToCamera - nearest) / max(farthest - nearest, 1e-6f), 0.0f, 1.0f));
    }
    // Ambient occlusion: 1 = open, 0 = fully occluded.
    vec3 origin = positionMaterial.xyz + normal * (frame.coneStartOffset * frame.grid.originVoxelSize.w);
    return vec3(1.0f - traceDiffuseCones(origin, normal, frame.coneStartOffset).a);
}

#endif
