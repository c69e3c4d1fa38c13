// The surface planes of ray visibility (ResourceSettings::rayVisibility): per texel, what lets a
// cone's sample tell on which side of the lit surfaces in its footprint it lies. The directional
// chains know from which direction a ray enters a texel but not where: a ray running along the
// inside of a block's face, or of a room's wall with a sunlit shell beyond it, that enters the
// texel holding them sees their lit outsides, as rays entering from outside do. Level 0 holds each
// occupied voxel's mean normal n (not renormalized) and its plane's offset dot(n, q − the grid's
// centre), q the surface point, both times the luminance of the voxel's light (radiance level 0);
// the mip chain holds plain means (mips.comp). Both are linear in the voxels, so a trilinear sample
// at any level gives dot(xyz, p − the grid's centre) − w = the light-weighted sum of p's signed
// distances to the planes in its footprint, and the luminance of the radiance sample the sum of
// the weights. Weighted by light, not opacity: a dim wall facing the sample and a bright face
// beyond it, turned away, cancel by opacity; what matters is where the footprint's light comes from.
#ifndef VCT_SURFACE_PLANES_H
#define VCT_SURFACE_PLANES_H

#include "bindings.h"
#include "cpp_glsl.h"
#include "luminance.h"

VCT_SHARED_BEGIN

// The weight of a voxel's plane per unit of its light's luminance as the radiance volume stores it.
// The brightest voxel stores up to 1024 (radianceStorageScale), and a plane's offset reaches 221
// voxels at 256³: unscaled, a sunlit wall's weighted offset passed float16's 65504 from 128³ on.
const float SURFACE_PLANE_WEIGHT = 1.0f / 1024.0f;

// A voxel's or a filtered sample's weight: the luminance of its light as the radiance volume
// stores it, scaled (above). The planes' level 0 and the test that reads them must weigh alike.
SHARED_FN float surfacePlaneWeight(vec3 storedRadiance) {
    return SURFACE_PLANE_WEIGHT * luminance(storedRadiance);
}

// Grid coordinates from the grid's centre, where the planes' offsets are measured from.
SHARED_FN vec3 fromGridCentre(vec3 gridPosition, float resolution) { return gridPosition - 0.5f * resolution; }

VCT_SHARED_END

#endif
