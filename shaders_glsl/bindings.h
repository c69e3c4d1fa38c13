// The descriptor slots (set 0, pushed) and specialization-constant ids of every shader, named once
// for GLSL and C++: a resource has one number in every shader that reads it, and the C++ that
// fills a slot (DescriptorPush, checked against the layout reflected from the SPIR-V) writes the
// same name. Slots need not be dense: a layout holds only the ones its shaders declare.
#ifndef VCT_BINDINGS_H
#define VCT_BINDINGS_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// The frame and the scene.
const uint FRAME_BINDING = 0u;               // FrameConstants (uniform)
const uint MATERIALS_BINDING = 1u;           // GpuMaterial[]
const uint LIGHTS_BINDING = 2u;              // GpuLight[]
const uint SHADOW_VIEWS_BINDING = 3u;        // ShadowView[]
const uint VERTICES_BINDING = 4u;            // GpuVertex[]
const uint INDICES_BINDING = 5u;             // uint[]
const uint TRIANGLE_MATERIALS_BINDING = 6u;  // uint[] per triangle
const uint EMITTER_TRIANGLES_BINDING = 8u;   // GpuEmitterTriangle[] of the area lights
const uint LTC_TABLE_BINDING = 9u;           // GpuLtcEntry[] (src/render/ltc_table.h)

// Set 1, bound per scene (not pushed): the scene's textures, sampler2D[TEXTURE_COUNT].
const uint TEXTURES_SET = 1u;
const uint COLOR_TEXTURES_BINDING = 0u;

// Shadow maps: compared (sampler2DArrayShadow) and raw depths for the blocker search.
const uint SUN_SHADOW_MAPS_BINDING = 10u;
const uint LOCAL_SHADOW_MAPS_BINDING = 11u;
const uint AREA_SHADOW_MAPS_BINDING = 12u;
const uint SUN_SHADOW_DEPTHS_BINDING = 13u;
const uint LOCAL_SHADOW_DEPTHS_BINDING = 14u;
const uint AREA_SHADOW_DEPTHS_BINDING = 15u;

// The G-buffer (gbuffer_packing.h).
const uint G_POSITION_BINDING = 16u;
const uint G_NORMAL_BINDING = 17u;
const uint G_BASE_COLOR_BINDING = 18u;
const uint G_EMISSIVE_BINDING = 19u;

// The voxel volumes (src/render/voxel_volumes.h), sampled or as storage images.
const uint VOXEL_RADIANCE_BINDING = 20u;      // premultiplied radiance; level 0 where written
const uint SURFACE_PLANES_BINDING = 21u;      // surface_planes.h
const uint DIRECTIONAL_VOXELS_BINDING = 22u;  // sampler3D[3] (directional_voxels.glsl)
const uint VOXEL_ALBEDO_BINDING = 23u;        // albedo, opacity
const uint VOXEL_NORMAL_BINDING = 24u;        // summed normal, surface share
const uint VOXEL_EMISSION_BINDING = 25u;
const uint GATHERED_LIGHT_BINDING = 26u;          // what the voxels' cones gathered (bounce_gather)
const uint OCCUPIED_VOXELS_BINDING = 27u;         // the occupied voxels' list (voxel_grid.h)
const uint OCCUPIED_LIST_BINDING = 28u;           // its WorkListHeader
const uint VOXEL_ACCUMULATION_BINDING = 29u;      // the voxelizer's integer sums, [ACCUM_CHANNELS]
const uint SKY_BINDING = 30u;                     // sky.glsl
const uint VOXELIZER_WORK_ITEMS_BINDING = 31u;    // the voxelizer's triangle chunks
const uint LIGHT_VOLUMES_BINDING = 32u;           // image3D[2]: radiance level 0 and the next bounce
const uint AREA_LIGHT_CACHE_BINDING = 33u;        // inject.comp.glsl
const uint FINER_LEVEL_BINDING = 34u;             // a mip step's source level (mips)
const uint COARSER_LEVEL_BINDING = 35u;           // and its destination
const uint FINER_LEAVING_BINDING = 36u;           // mips_anisotropic: what leaves the finer level
const uint COARSER_LEAVING_BINDING = 37u;         // and the coarser

// The reduced diffuse cones (reduced_diffuse.glsl): per reduced texel its light, its
// representative's position and normal, this frame's and the last one's; per sample the light.
const uint REDUCED_LIGHT_BINDING = 40u;
const uint REDUCED_POSITIONS_BINDING = 41u;
const uint REDUCED_NORMALS_BINDING = 42u;
const uint LAST_REDUCED_LIGHT_BINDING = 43u;
const uint LAST_REDUCED_POSITIONS_BINDING = 44u;
const uint LAST_REDUCED_NORMALS_BINDING = 45u;
const uint DIFFUSE_SAMPLES_BINDING = 46u;       // per sample (the shading pass reads it)
const uint LAST_DIFFUSE_SAMPLES_BINDING = 47u;
const uint LAST_G_POSITION_BINDING = 48u;       // the last frame's G-buffer
const uint LAST_G_NORMAL_BINDING = 49u;
const uint TRACED_SAMPLES_BINDING = 50u;        // the representatives that trace this frame
const uint TRACED_LIST_BINDING = 51u;
const uint EDGE_SAMPLES_BINDING = 52u;          // the samples the upsampling could not fill
const uint EDGE_LIST_BINDING = 53u;
const uint FALLBACK_SAMPLES_BINDING = 54u;      // the samples that trace their own cones
const uint FALLBACK_LIST_BINDING = 55u;
const uint LISTED_SAMPLES_BINDING = 56u;        // diffuse_trace_list: a list above,
const uint LISTED_SAMPLES_LIST_BINDING = 57u;   // its header,
const uint LISTED_TARGET_BINDING = 58u;         // and where its light goes

// The image's end, and the tests' probes.
const uint SUPERSAMPLED_BINDING = 60u;  // resolve: the shading pass's samples
const uint RESOLVED_BINDING = 61u;      // and the image (the running mean of still frames)
const uint DISPLAYED_BINDING = 62u;     // tonemap: the radiance the viewer shows
const uint CONE_PROBES_BINDING = 63u;   // cone_probe.comp.glsl
const uint CONE_PROBE_RESULTS_BINDING = 64u;

// Specialization constants. Those of one pipeline are distinct; the empty-space skipping's is the
// same in every shader that traces cones (cone_tracing.glsl).
const uint TEXTURE_COUNT_CONSTANT_ID = 0u;      // the scene's texture array
const uint ALPHA_TESTED_CONSTANT_ID = 1u;       // gbuffer.frag
const uint MASK_TEXTURES_CONSTANT_ID = 1u;      // voxelize.comp
const uint AREA_LIGHTS_CACHED_CONSTANT_ID = 0u;  // inject.comp
const uint FINER_IS_SCENE_LEVEL_CONSTANT_ID = 0u;  // mips_anisotropic.comp
const uint WITH_DEBUG_VIEWS_CONSTANT_ID = 0u;   // shade.frag, ids 0-6
const uint TRACES_DIFFUSE_CONES_CONSTANT_ID = 1u;
const uint TRACES_SPECULAR_CONE_CONSTANT_ID = 2u;
const uint WITH_AREA_LIGHTS_CONSTANT_ID = 3u;
const uint WITH_SUN_SHADOWS_CONSTANT_ID = 4u;
const uint WITH_LOCAL_SHADOWS_CONSTANT_ID = 5u;
const uint WITH_AREA_LIGHT_SPECULAR_CONSTANT_ID = 6u;
const uint SKIP_EMPTY_SPACE_CONSTANT_ID = 7u;

VCT_SHARED_END

#endif
