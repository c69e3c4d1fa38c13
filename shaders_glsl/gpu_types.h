// Structs that cross the CPU/GPU boundary, declared once for C++ and GLSL.
// Members are ordered so that std140/std430 offsets equal C++'s (static_asserts in src/render/frame_constants.h).
#ifndef VCT_GPU_TYPES_H
#define VCT_GPU_TYPES_H

#include "bindings.h"
#include "cpp_glsl.h"
#include "texture_transform.h"
#include "voxel_grid.h"

VCT_SHARED_BEGIN

struct GpuVertex {
    vec4 positionU;  // xyz position, w texture u (TEXCOORD_0)
    vec4 normalV;    // xyz normal, w texture v (TEXCOORD_0)
    vec4 texCoord1;  // xy TEXCOORD_1 (TEXCOORD_0 where the file has none), zw unused
    vec4 tangent;    // the file's TANGENT (xyz unit, w handedness ±1), 0 where it has none (Vertex::tangent)
};

struct GpuMaterial {
    vec4 baseColorFactor;  // linear rgb, alpha
    vec4 emission;         // rgb radiance from the front face, before the emissive texture
    vec4 voxelEmission;    // rgb emission × the emissive texture's mean (voxelEmission() in material_textures.h),
                           // w the share of the surface the voxels see (voxelCoverage() there)
    float metallic;
    float roughness;
    float specularWeight;
    int baseColorTexture;  // -1 = none
    int emissiveTexture;   // -1 = none
    int metallicRoughnessTexture;  // -1 = none; linear, blue scales metallic, green roughness (glTF)
    int normalTexture;             // -1 = none; linear, tangent space (glTF)
    float normalScale;             // scales the normal texture's x and y
    int occlusionTexture;          // -1 = none; linear, red scales the indirect light (glTF)
    float occlusionStrength;       // occlusion = 1 + strength · (red − 1)
    uint alphaMode;                // ALPHA_OPAQUE, ALPHA_MASK or ALPHA_BLEND (alpha_coverage.h)
    float alphaCutoff;             // ALPHA_MASK: coverage (base colour alpha) below it is a hole
    // Where each texture is read (texture_transform.h).
    GpuTextureTransform baseColorTransform;
    GpuTextureTransform emissiveTransform;
    GpuTextureTransform metallicRoughnessTransform;
    GpuTextureTransform normalTransform;
    GpuTextureTransform occlusionTransform;
};

struct GpuLight {
    vec4 radiantIntensity;  // rgb colour × intensity (cd, or lux for directional), w = type
    vec4 positionRange;     // xyz world position, w range (0 = infinite)
    vec4 direction;         // xyz direction the light travels
    vec4 spotShadow;        // x inner cone angle, y outer cone angle, z first shadow view, w shadow view count
    vec4 cascades;          // a sun: x its first cascade's view (the finest), y their count (0: none)
    // An area light (LIGHT_AREA) reads them as: rgb mean radiance; xyz its shadow cube's eye, w its
    // radius; xyz its front normal, w its area; x its first emitter triangle, y their count.
};

// One triangle of an area light: corners wound so that cross(b − a, c − a) points out of the
// emitting front face, and its radiance in their w components (r, g, b).
struct GpuEmitterTriangle {
    vec4 a;
    vec4 b;
    vec4 c;
};

// One rendered shadow map: a sun or spot light has one, a point light six (cube faces).
struct ShadowView {
    mat4 viewProjection;
    vec4 params;  // x array (0 = sun maps, 1 = local maps), y layer, z texel size at unit distance, w 1 = perspective
    vec4 depthRange;  // perspective views: x near, y far (their depth d maps to f(d − n) / (d(f − n)))
                      // z: the share of the layer's side the view covers (1 but for a sun's cascade,
                      // drawn at the image's scale, render/sun_cascades.h), w: its tile of the layer
};

// Where in its layer (uv) a view's map starts: (0, 0), but for a sun's cascade, one tile of a grid
// of them that share a layer, in rows from the corner.
SHARED_FN vec2 shadowTileCorner(ShadowView view) {
    float share = view.depthRange.z;
    float tilesPerSide = floor(1.0f / share + 0.5f);
    float row = floor(view.depthRange.w / tilesPerSide);
    return vec2(view.depthRange.w - row * tilesPerSide, row) * share;
}

// Bits of FrameConstants.componentFlags: which light components the final image contains.
const uint SHOW_DIRECT_DIFFUSE = 1u;
const uint SHOW_DIRECT_SPECULAR = 2u;
const uint SHOW_INDIRECT_DIFFUSE = 4u;
const uint SHOW_INDIRECT_SPECULAR = 8u;
const uint SHOW_AMBIENT_OCCLUSION = 16u;
const uint SHOW_EMISSION = 32u;
const uint USE_SHADOWS = 64u;
// Emissive surfaces light the room as area lights; without it their emission is put into the
// voxels and reaches other surfaces only through the cones (the classic VCT way).
const uint USE_AREA_LIGHTS = 128u;
// The sky seen directly (pixels where the camera sees no surface): part of direct light, as a lamp
// seen is, but not an emissive surface, so `--disable emission` leaves it.
const uint SHOW_SKY = 256u;
// Not a component: cones stop where a ray along them meets a surface (ResourceSettings::rayVisibility).
const uint RAY_VISIBILITY = 512u;
// Not a component: six directional mip chains instead of one (ResourceSettings::anisotropicVoxels).
const uint ANISOTROPIC_VOXELS = 1024u;
// The flags the voxels' light depends on (inject.comp.glsl): a change converges it again.
const uint VOXEL_LIGHT_FLAGS = USE_SHADOWS | USE_AREA_LIGHTS;


// The frame's constants, one uniform block (std140: every member sits at its natural offset, which
// the C++ side checks with static_asserts).
struct FrameConstants {
    mat4 viewProjection;
    mat4 inverseViewProjection;
    VoxelGridParams grid;
    vec3 cameraPosition;
    uint lightCount;
    uint shadowViewCount;
    uint componentFlags;     // SHOW_* / USE_* / RAY_VISIBILITY / ANISOTROPIC_VOXELS
    float diffuseRingTurn;   // the screen's diffuse ring turned by this share of its cones' spacing
    uint debugView;          // DEBUG_*
    vec2 renderSize;         // of the render target, in pixels
    vec2 inverseRenderSize;
    float ambientFactor;
    float shadowNormalOffset;  // texels
    float pcfRadius;           // texels
    float radianceScale;       // the volume stores radiance × scale to stay inside float16

    // Voxel cone tracing (Crassin et al. 2011). Distances are in voxels of the finest level.
    float coneTanHalfAperture;  // of the diffuse cones
    float coneStep;             // fraction of the cone's diameter
    float coneMaxDistance;
    float coneStartOffset;      // along the normal
    float aoFalloff;            // per voxel
    float coneStopOpacity;
    float diffuseCentreWeight;
    uint diffuseConeCount;
    float environmentTurns;  // the environment image turned about +Y, in [0, 1) turns (equirectangular.h)
    uint debugVoxelMip;   // the mip level the voxel debug views show
    uint diffuseDownscale;  // diffuse cones traced once per diffuseDownscale² samples (1 = every sample)
    uint firstAreaLight;  // lights[firstAreaLight, lightCount) are the area lights, after the punctual ones
    vec4 environment;  // rgb: the sky's radiance (Scene::environment), seen by cones that leave the grid;
                       // w = 1: an environment image is bound, and rgb multiplies it (sky.glsl)
    float specularConeMaxTan;  // tan(half-aperture) of the widest specular cone
    // With ray visibility, which of its five beams each screen cone traces this turn (DiffuseBeam in
    // src/render/settings.h): ALL_BEAMS, AXIS_BEAM, or BEAM_AROUND_AXIS at diffuseBeamAzimuth radians.
    uint diffuseBeam;
    float diffuseBeamAzimuth;
    float unused0;  // std140 rounds the block to 16 bytes: room for the next setting
};

// FrameConstants.diffuseBeam (cone_tracing.glsl, traceDiffuseCone).
const uint ALL_BEAMS = 0u;
const uint AXIS_BEAM = 1u;
const uint BEAM_AROUND_AXIS = 2u;

// What the shading pass shows instead of light (FrameConstants.debugView), for understanding.
const uint DEBUG_NONE = 0u;
const uint DEBUG_BASE_COLOR = 1u;
const uint DEBUG_NORMAL = 2u;
const uint DEBUG_DEPTH = 3u;
const uint DEBUG_AMBIENT_OCCLUSION = 4u;
const uint DEBUG_VOXEL_ALBEDO = 5u;
const uint DEBUG_VOXEL_NORMAL = 6u;
const uint DEBUG_VOXEL_RADIANCE = 7u;
const uint DEBUG_SUN_CASCADES = 8u;
const uint DEBUG_VIEW_COUNT = 9u;


VCT_SHARED_END

#endif
