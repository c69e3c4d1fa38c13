// What the material textures amount to where a pass cannot sample them per texel.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "texture_transform.h"

namespace vct {

// The transform through which the renderer and the path tracer read `reference`'s texture.
glsl::GpuTextureTransform textureTransform(const TextureReference& reference);

// The coordinates at which `vertex` reads the texture of `reference`.
glm::vec2 textureCoordinates(const TextureReference& reference, const Vertex& vertex);

// The texel of a row or column of `size` texels at whole texel index `texel` (floored, any value;
// not finite reads texel 0), wrapped as `wrap` says.
uint32_t wrapTexel(double texel, uint32_t size, TextureWrap wrap);

// The sRGB decoding function (IEC 61966-2-1).
float srgbToLinear(float encoded);

// The mean of the texture's sRGB-decoded RGB over all its texels; white for an empty texture.
glm::vec3 meanLinearColor(const Texture& texture);

// The mean of the texture's sRGB-decoded RGB over the triangle with corners uv[0..2] (texture
// coordinates, wrapped as the texture says), sampled at the centroids of a regular subdivision of the triangle fine
// enough for about two samples per texel it covers (at most 64 × 64 sub-triangles); white for an
// empty texture.
glm::vec3 meanLinearColorOverTriangle(const Texture& texture, const glm::vec2 uv[3]);

// The surface's share at a point where the base colour's alpha (factor × texture) is `alpha`, as
// glTF's alphaMode says: Opaque 1; Mask 1 where alpha reaches alphaCutoff, else 0 (a hole); Blend alpha.
float coverageOfAlpha(const Material& material, float alpha);

// The mean radiance the triangle (corners v[0..2]) emits from its front face: emission × its emissive
// texture × its coverage (coverageOfAlpha, from the base colour's alpha) at each point, averaged as
// meanLinearColorOverTriangle averages, over both textures' coordinates. A MASK emitter's holes and
// a BLEND emitter's transparent parts emit nothing, as the camera and the path tracer see through them.
glm::vec3 emittedRadianceOverTriangle(const Scene& scene, const Material& material, const Vertex* const v[3]);

// The radiance the voxelizer gives the material's surfaces: emission × the mean of its emissive
// texture. An approximation: the voxels of a surface whose texture glows in a few places glow
// evenly and faintly, with the same total power (for a texture mapped once over the surface).
glm::vec3 voxelEmission(const Scene& scene, const Material& material);
// Whether the material emits at all: its voxelEmission is not black.
bool emitsLight(const Scene& scene, const Material& material);

// The share of the material's surface that is there, in [0, 1]: its coverage (base colour alpha,
// factor × texture) as a mean over the texture, the way voxelEmission treats emission. Opaque: 1.
// Mask: the fraction of the texels whose alpha reaches alphaCutoff (1 or 0 without a texture).
// Blend: the mean alpha. The voxelizer takes it where the material has no base colour texture, and
// skips a material whose share is 0; with a texture it reads each voxel's own footprint.
float voxelCoverage(const Scene& scene, const Material& material);

// Whether the voxelizer reads a MASK material's coverage from its base colour texture, over each
// voxel's footprint (voxelize.comp), rather than voxelCoverage's one number.
bool masksVoxelsByTexture(const Scene& scene, const Material& material);

}  // namespace vct
