#include "render/light_table.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace vct {
namespace {

// A host-visible storage buffer holding `items` (at least one element's room).
template <typename T>
Buffer hostArray(GpuContext& context, const std::vector<T>& items) {
    Buffer buffer(context, VkDeviceSize(std::max<size_t>(items.size(), 1) * sizeof(T)),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
    // An empty vector's data() may be null: memcpy must not see it (UBSan).
    if (!items.empty()) std::memcpy(buffer.mapped, items.data(), items.size() * sizeof(T));
    return buffer;
}

}  // namespace

void LightTable::upload(GpuContext& context, ShadowLayout layout) {
    layout_ = std::move(layout);
    lights_ = hostArray(context, layout_.lights);
    shadowViews_ = hostArray(context, layout_.views);
    emitterTriangles_ = hostArray(context, layout_.emitterTriangles);
}

}  // namespace vct
