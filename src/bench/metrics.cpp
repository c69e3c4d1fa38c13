#include "bench/metrics.h"

#include <cmath>
#include <limits>
#include <string>

#include "error.h"

namespace vct::bench {
namespace {

void requireSameSize(const Image& a, const Image& b, const char* what) {
    if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size())
        throw Error(std::string(what) + ": the images differ in size (" + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " against " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                    ")");
}

}  // namespace

ImageError compareImages(const Image& image, const Image& reference, const MetricTolerances& tolerances) {
    requireSameSize(image, reference, "comparing with the reference");
    ImageError error;
    const size_t pixels = size_t(reference.width) * reference.height;
    if (pixels == 0) return error;

    double referenceChannelSum = 0.0, referenceLuminanceSum = 0.0, imageLuminanceSum = 0.0;
    for (size_t i = 0; i < pixels; ++i) {
        const float* r = &reference.rgb[3 * i];
        referenceChannelSum += double(r[0]) + r[1] + r[2];
        referenceLuminanceSum += luminance(r);
        imageLuminanceSum += luminance(&image.rgb[3 * i]);
    }
    const double meanChannel = referenceChannelSum / double(3 * pixels);
    const double meanLuminance = referenceLuminanceSum / double(pixels);
    const double epsilon = std::pow(tolerances.relativeEpsilon * meanChannel, 2.0);

    double relativeSum = 0.0, squaredSum = 0.0;
    size_t off = 0;
    for (size_t i = 0; i < pixels; ++i) {
        const float* x = &image.rgb[3 * i];
        const float* r = &reference.rgb[3 * i];
        for (int c = 0; c < 3; ++c) {
            const double d = double(x[c]) - double(r[c]);
            squaredSum += d * d;
            // A black reference with ε = 0 (a black image) has nothing to be relative to.
            const double denominator = double(r[c]) * r[c] + epsilon;
            relativeSum += denominator > 0.0 ? d * d / denominator : (d == 0.0 ? 0.0 : d * d);
        }
        const double lr = luminance(r);
        const double tolerance = tolerances.offFraction * std::fabs(lr) + tolerances.offFloor * meanLuminance;
        if (!(std::fabs(luminance(x) - lr) <= tolerance)) ++off;  // NaN counts as off
    }
    error.relMse = relativeSum / double(3 * pixels);
    error.rmse = std::sqrt(squaredSum / double(3 * pixels));
    error.luminanceRatio = referenceLuminanceSum > 0.0 ? imageLuminanceSum / referenceLuminanceSum
                           : imageLuminanceSum == 0.0  ? 1.0
                                                       : std::numeric_limits<double>::infinity();
    error.shareOff = double(off) / double(pixels);
    return error;
}

double shadowedLuminanceRatio(const Image& indirect, const Image& referenceIndirect, const Image& referenceDirect,
                              double shadowFraction) {
    requireSameSize(indirect, referenceIndirect, "comparing with the reference");
    requireSameSize(referenceDirect, referenceIndirect, "comparing with the reference");
    const size_t pixels = size_t(referenceDirect.width) * referenceDirect.height;
    double directSum = 0.0;
    for (size_t i = 0; i < pixels; ++i) directSum += luminance(&referenceDirect.rgb[3 * i]);
    const double shadowBelow = pixels ? shadowFraction * directSum / double(pixels) : 0.0;
    double imageSum = 0.0, referenceSum = 0.0;
    for (size_t i = 0; i < pixels; ++i) {
        if (!(luminance(&referenceDirect.rgb[3 * i]) < shadowBelow)) continue;
        imageSum += luminance(&indirect.rgb[3 * i]);
        referenceSum += luminance(&referenceIndirect.rgb[3 * i]);
    }
    return referenceSum > 0.0 ? imageSum / referenceSum : std::numeric_limits<double>::quiet_NaN();
}

Image addImages(const Image& a, const Image& b) {
    requireSameSize(a, b, "adding images");
    Image sum = a;
    for (size_t i = 0; i < sum.rgb.size(); ++i) sum.rgb[i] += b.rgb[i];
    return sum;
}

}  // namespace vct::bench
