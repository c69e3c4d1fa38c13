// Visibility at the finest scale, for cones that pay for it (ResourceSettings::rayVisibility): the
// distance along a ray to the first occupied voxel of the grid's level 0. The isotropic chain's
// opacity is a mean of its children's, so a texel whose opacity is 0 holds no surface at any finer
// level, and the ray skips whole empty blocks of up to 2^VISIBILITY_SKIP_LEVELS voxels. A wall a
// voxel thick stops it from either side, whatever the width of the cone it gates; the coarse
// texels a cone reads straddle such a wall and blend both its sides. Requires voxelRadiance.
#ifndef VCT_VISIBILITY_RAY_GLSL
#define VCT_VISIBILITY_RAY_GLSL

const float NO_HIT = 1e9f;
const int VISIBILITY_SKIP_LEVELS = 4;
const int VISIBILITY_MAX_STEPS = 256;

bool occupiedAt(ivec3 cell, int level) { return texelFetch(voxelRadiance, cell, level).a > 0.0f; }

// From `start` (grid coordinates) along unit `direction`, at most `maxDistance` voxels: NO_HIT
// where the ray leaves the grid first. `maxLevel`: the chain's coarsest level.
float firstSurfaceDistance(vec3 start, vec3 direction, float maxDistance, float resolution, int maxLevel) {
    vec3 safe = mix(direction, vec3(1e-6f), lessThan(abs(direction), vec3(1e-6f)));
    vec3 inverse = 1.0f / safe;
    vec3 ahead = step(vec3(0.0f), safe);
    int topLevel = min(VISIBILITY_SKIP_LEVELS, maxLevel);
    float t = 0.0f;
    for (int i = 0; i < VISIBILITY_MAX_STEPS && t <= maxDistance; ++i) {
        vec3 p = start + direction * t;
        if (any(lessThan(p, vec3(0.0f))) || any(greaterThanEqual(p, vec3(resolution)))) return NO_HIT;
        ivec3 cell = ivec3(floor(p));
        if (occupiedAt(cell, 0)) return t;
        // The coarsest empty block around the cell, then on to where the ray leaves it.
        int level = 0;
        while (level < topLevel && !occupiedAt(cell >> (level + 1), level + 1)) ++level;
        float size = float(1 << level);
        vec3 low = vec3((cell >> level) << level);
        vec3 exits = (low + ahead * size - start) * inverse;
        t = max(min(exits.x, min(exits.y, exits.z)), t) + 1e-3f;
    }
    return NO_HIT;
}

#endif
