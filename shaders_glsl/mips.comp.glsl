#version 460
// One level of the radiance mip chain: each texel is the mean of its 2×2×2 children. The
// volume holds opacity-premultiplied radiance, so a plain mean is the opacity-weighted mean of
// the colours and the mean coverage of the opacity (Crassin et al. 2011, section 4).
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(set = 0, binding = FINER_LEVEL_BINDING, rgba16f) uniform readonly image3D finer;
layout(set = 0, binding = COARSER_LEVEL_BINDING, rgba16f) uniform writeonly image3D coarser;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, imageSize(coarser)))) return;
    vec4 sum = vec4(0.0f);
    for (int child = 0; child < 8; ++child)
        sum += imageLoad(finer, texel * 2 + ivec3(child & 1, (child >> 1) & 1, child >> 2));
    imageStore(coarser, texel, sum * 0.125f);
}
