#version 460
// The viewer's present pass: the renderer's linear radiance onto the swapchain image, as
// `vct render --out x.png` writes it: shaders_glsl/tone_curve.h, shared with src/io/image_io.cpp.
// Debug views that hold colours already (base colour, normals, depth, AO, voxel albedo and normal)
// skip the tone curve so their values read directly.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "present.h"
#include "tone_curve.h"

layout(set = 0, binding = DISPLAYED_BINDING) uniform sampler2D radiance;
layout(push_constant) uniform Push { TonemapPush push; };
layout(location = 0) out vec4 color;

void main() {
    vec3 value = textureLod(radiance, (gl_FragCoord.xy - push.areaOffset) * push.inverseAreaSize, 0.0f).rgb;
    // NaN and infinity (a broken pixel) show black, as in the PNG writer.
    bvec3 broken = bvec3(isnan(value.x) || isinf(value.x), isnan(value.y) || isinf(value.y),
                         isnan(value.z) || isinf(value.z));
    value = mix(value, vec3(0.0f), broken);
    vec3 mapped = push.applyToneCurve != 0u ? toneMap(value * push.exposure, push.toneCurve) : clamp(value, 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c) mapped[c] = encodeSrgb(mapped[c]);
    color = vec4(mapped, 1.0f);
}
