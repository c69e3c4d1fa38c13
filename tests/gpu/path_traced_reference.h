// The path tracer's image of a scene, for GPU tests that compare the renderer with it.
#pragma once

#include <cstdint>

#include "path_tracer.h"

namespace vct::test {

// The path tracer's direct light of `scene` from its first camera, size × size at 256 samples a pixel.
inline Image pathTracedDirectLight(const Scene& scene, uint32_t size) {
    pt::PathTracer tracer = pt::createPathTracer(scene);
    pt::RenderSettings settings;
    settings.width = settings.height = size;
    settings.samplesPerPixel = 256;
    settings.component = pt::Component::Direct;
    settings.threads = 1;
    settings.camera = scene.cameras.front();
    return pt::render(tracer, settings).image;
}

}  // namespace vct::test
