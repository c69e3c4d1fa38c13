// Shadow cascades for a sun (cascaded shadow maps, Engel 2006; Dimitrov 2007): orthographic maps
// fitted to slices of the camera's view, each slice a quarter as deep as the one beyond it, used
// for shading where the map fitted to the whole scene has texels coarser than the image's pixels.
// Over a 1 km landscape that map's texels are a third of a metre, and a house's shadows are blobs.
//
// Where they are needed is a matter of where the camera stands, not of the scene's size: the
// scene-fitted map's texel matches a pixel at a distance d* that is the same fraction of the
// scene's radius in every scene (2 / (map size × pixel angle)), so cascades cover view distances up
// to d*, and only while some geometry is nearer the camera than d*. A camera outside a room, or in
// its middle at a small image size, gets none, and the image is what the scene-fitted map gives.
//
// The voxels' light keeps the scene-fitted map: it must not change when the camera moves.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_types.h"
#include "scene/scene.h"

namespace vct {

// What a sun's cascades are fitted to, in the renderer's frame.
struct CascadeView {
    Camera camera;
    float aspect = 1.0f;        // image width / height
    uint32_t imageHeight = 1;   // pixels
    float nearestGeometry = 0;  // from the camera to the nearest triangle's bounding box
};

// Each slice's farther view distance, finest slice first (each covers from the next nearer one's
// end, the first from the camera): none when no geometry is nearer than the distance where
// `sceneTexel` (the scene-fitted map's texel) covers a pixel; at most `maxCascades`.
std::vector<float> cascadeDistances(const CascadeView& view, float sceneTexel, uint32_t maxCascades);

// An orthographic view along `direction` that holds the view slice between `nearDistance` and
// `farDistance` (its bounding sphere, with the texel's snapping), and in depth every part of the
// scene between it and the sun. Its texel grid is fixed in the world: a camera that moves shifts
// it by whole texels, so shadow edges do not crawl. The map is `mapSize` texels a side, drawn into
// tile `tile` of a layer `layerSize` a side (depthRange.z holds the share of the side it covers, w
// the tile: glsl::shadowTileCorner). Its params hold the texel (z); the caller sets the array and
// layer (x, y).
glsl::ShadowView cascadeShadowView(glm::vec3 direction, const CascadeView& view, float nearDistance, float farDistance,
                                   const Bounds& sceneBounds, uint32_t mapSize, uint32_t layerSize, uint32_t tile);

// A cascade's map side for an image `imageHeight` pixels high: eight texels a pixel along the
// image's height, a power of two, at most the sun array's `layerSize`. The shadows' error falls with
// the texel (the landscape's direct light at 128², relMSE: 0.030 at four texels a pixel, 0.0084 at
// eight, 0.0031 at sixteen), and the cost rises with its square: a 4096² cascade for a 128² image
// cost lavapipe 30 ms a layer, every frame the camera moved.
uint32_t cascadeMapSize(uint32_t imageHeight, uint32_t layerSize);

// Each triangle's bounding box.
std::vector<Bounds> triangleBoxes(const Scene& scene);
// The distance from `point` to the nearest of the boxes (0 inside one; infinity with none).
float nearestBoxDistance(const std::vector<Bounds>& boxes, glm::vec3 point);

}  // namespace vct
