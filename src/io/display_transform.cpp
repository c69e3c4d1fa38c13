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
        const double pixel = luminance(&image.rgb[i]);
        if (!(pixel > 0.0) || !std::isfinite(pixel)) continue;
        logSum += std::log(pixel);
        ++lit;
    }
    if (lit == 0) return 1.0f;
    return float(double(kMiddleGrey) / std::exp(logSum / double(lit)));
}

float exposureFromStops(float ev) { return std::exp2(ev); }

}  // namespace vct
