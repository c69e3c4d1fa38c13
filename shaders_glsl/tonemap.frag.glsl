#version 460
// The viewer's present pass: the renderer's linear radiance onto the swapchain image, as
// `vct render --out x.png` writes it: shaders_glsl/tone_curve.h, shared with src/io/image_io.cpp.
// Debug views that hold colours already (base colour, normals, depth, AO, voxel albedo and normal)
// skip the tone curve so their values read directly.
#extension GL_GOOGLE_include_directive : require
#include "present.h"
#include "tone_curve.h"

layout(set = 0, binding = 0) uniform sampler2D radiance;
layout(push_constant) uniform Push { TonemapPush push; };
layout(location = 0) out vec4 color;

void main() {
    vec3 value = textureLod(radiance, (gl_FragCoord.xy - push.areaOffset) * push.inverseAreaSize, 0.0f).rgb;
    vec3 mapped;
    for (int c = 0; c < 3; ++c) {
        // NaN and infinity (a broken pixel) show black, as in the PNG writer.
        float channel = isnan(value[c]) || isinf(value[c]) ? 0.0f : value[c];
        mapped[c] = encodeSrgb(push.applyToneCurve != 0u ? tonemapAces(channel * push.exposure)
                                                         : clamp(channel, 0.0f, 1.0f));
    }
    color = vec4(mapped, 1.0f);
}
