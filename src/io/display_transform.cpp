#include "io/display_transform.h"

#include <cmath>

namespace vct {

const char* toneCurveName(ToneCurve curve) { return curve == ToneCurve::Aces ? "aces" : "pbr-neutral"; }

std::optional<ToneCurve> parseToneCurve(const std::string& name) {
    if (name == "pbr-neutral") return ToneCurve::PbrNeutral;
    if (name == "aces") return ToneCurve::Aces;
    return std::nullopt;
}

float automaticExposure(const Image& image) {
    double logSum = 0.0;
    size_t lit = 0;
    for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        const float luminance = 0.2126f * image.rgb[i] + 0.7152f * image.rgb[i + 1] + 0.0722f * image.rgb[i + 2];
        if (!(luminance > 0.0f) || !std::isfinite(luminance)) continue;
        logSum += std::log(double(luminance));
        ++lit;
    }
    if (lit == 0) return 1.0f;
    return float(double(kMiddleGrey) / std::exp(logSum / double(lit)));
}

float exposureFromStops(float ev) { return std::exp2(ev); }

}  // namespace vct
