#version 460
// One level of one directional mip chain (Crassin et al. 2011, section 4.1, "anisotropic
// voxels"). For rays travelling along +x, say, each pair of children along x is composited front
// to back (the nearer child occludes the farther one), and the four pairs are averaged. A wall
// across a texel then stays opaque for rays crossing it, where a plain average would make it
// 1/size opaque and let wide cones see through thin walls.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(set = 0, binding = 0, rgba16f) uniform readonly image3D finer;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image3D coarser;
// 0..5 = +x, −x, +y, −y, +z, −z: the direction rays travel through this volume.
layout(push_constant) uniform Push { uint direction; };

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(texel, imageSize(coarser)))) return;
    int axis = int(direction / 2u);
    bool positive = (direction & 1u) == 0u;
    ivec3 along = ivec3(0);
    along[axis] = 1;
    vec4 sum = vec4(0.0f);
    for (int a = 0; a < 2; ++a) {
        for (int b = 0; b < 2; ++b) {
            ivec3 across = ivec3(0);
            across[(axis + 1) % 3] = a;
            across[(axis + 2) % 3] = b;
            ivec3 first = texel * 2 + across;
            vec4 low = imageLoad(finer, first);
            vec4 high = imageLoad(finer, first + along);
            vec4 near = positive ? low : high;
            vec4 far = positive ? high : low;
            sum += near + (1.0f - near.a) * far;  // premultiplied front-to-back "over"
        }
    }
    imageStore(coarser, texel, sum * 0.25f);
}
