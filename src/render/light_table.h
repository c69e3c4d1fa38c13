// The lights as the shaders read them (lights.h): a ShadowLayout's punctual and area lights, the
// area lights' triangles and every shadow map's view, in host-visible buffers the passes bind.
#pragma once

#include "gpu/context.h"
#include "gpu/resources.h"
#include "render/shadow_pass.h"

namespace vct {

class LightTable {
public:
    // New buffers holding `layout` (at least one element each: Vulkan forbids empty buffers).
    void upload(GpuContext& context, ShadowLayout layout);
    const ShadowLayout& layout() const { return layout_; }
    LightBuffers buffers() const { return {lights_.buffer, shadowViews_.buffer, emitterTriangles_.buffer}; }

private:
    ShadowLayout layout_;
    Buffer lights_;
    Buffer shadowViews_;
    Buffer emitterTriangles_;
};

}  // namespace vct
