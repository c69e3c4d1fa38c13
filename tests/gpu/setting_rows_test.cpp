// Every shading setting of the setting table (src/render/setting_table.h) reaches the image: a row
// whose member the renderer forgot to hand to the shaders would be an option, a slider and a bench
// column that change nothing.
#include "gpu_test.h"
#include "render/renderer.h"
#include "render/setting_table.h"
#include "scene/load.h"

namespace vct::test {
namespace {

class SettingRows : public GpuTest {};

TEST_F(SettingRows, EachShadingRowChangesTheImage) {
    // The glossy Cornell box with a little ambient light, so that every cone setting shows: the
    // diffuse cones, the sphere's specular cone, and the occlusion the ambient term reads.
    const Scene scene = loadScene("cornell-metal");
    RenderSettings base = smallRenderSettings(32, RenderMode::Full);
    base.shading.ambientFactor = 0.1f;
    base.shading.diffuseConeTurns = 1;
    Renderer renderer(gpu(), scene, base);
    renderer.renderSettled();
    const Image before = renderer.readImage();
    size_t checked = 0;
    for (const SettingRow& row : settingTable()) {
        if (row.group != SettingGroup::Cones && row.group != SettingGroup::Light) continue;
        // The far end of its range from where it is (the other name for a names-only row).
        const double value = row.get(base);
        const double other = row.namesOnly
                                 ? (row.names.front().value != value ? row.names.front().value : row.names.back().value)
                                 : (value - row.min > row.max - value ? row.min : row.max);
        RenderSettings changed = base;
        row.set(changed, other);
        renderer.setShading(changed.shading);
        renderer.renderSettled();
        EXPECT_FALSE(sameImages(renderer.readImage(), before))
            << "--" << row.option << " " << settingText(row, other) << " left the image as it was";
        renderer.setShading(base.shading);
        ++checked;
    }
    EXPECT_GE(checked, 10u);
}

}  // namespace
}  // namespace vct::test
