// How an image is made for people (PNG files, the viewer's window): its linear radiance × an
// exposure, a tone curve (shaders_glsl/tone_curve.h), then sRGB. PFM output never goes through it.
#pragma once

#include <optional>
#include <string>

#include "io/image_io.h"
#include "tone_curve.h"

namespace vct {

enum class ToneCurve : uint32_t { PbrNeutral = glsl::TONE_CURVE_PBR_NEUTRAL, Aces = glsl::TONE_CURVE_ACES };

// "pbr-neutral" or "aces".
const char* toneCurveName(ToneCurve curve);
std::optional<ToneCurve> parseToneCurve(const std::string& name);

struct DisplayTransform {
    float exposure = 1.0f;  // radiance multiplier
    ToneCurve curve = ToneCurve::PbrNeutral;
};

// The luminance the automatic exposure maps the image's log-average luminance to: middle grey.
constexpr float kMiddleGrey = 0.18f;

// The exposure (a radiance multiplier) that maps the log-average luminance of the image's lit
// pixels to kMiddleGrey, as engines' automatic exposure does. Black pixels (a black sky, the
// background) do not count, so an object against nothing is exposed for itself. 1 for an image
// with no light at all.
float automaticExposure(const Image& image);

// An exposure given in stops (EV): 2^ev.
float exposureFromStops(float ev);

}  // namespace vct
