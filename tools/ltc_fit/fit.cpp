#include "fit.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "ltc.h"
#include "ltc_distribution.h"
#include "nelder_mead.h"

namespace vct::ltc {
namespace {

glm::dmat3 ltcMatrix(const Parameters& p, glm::dvec3 meanDirection) {
    // The cosine's axis: the lobe's mean direction turned by p[3] in the plane of incidence.
    const double c = std::cos(p[3]), s = std::sin(p[3]);
    const glm::dvec3 z(c * meanDirection.x + s * meanDirection.z, 0.0, c * meanDirection.z - s * meanDirection.x);
    const glm::dvec3 y(0.0, 1.0, 0.0), x = glm::cross(y, z);
    // GLM's constructor takes columns: [[m00 0 m02] [0 m11 0] [0 0 1]].
    const glm::dmat3 shape(glm::dvec3(p[0], 0.0, 0.0), glm::dvec3(0.0, p[1], 0.0), glm::dvec3(p[2], 0.0, 1.0));
    return glm::dmat3(x, y, z) * shape;
}

Parameters constrained(Parameters p, bool isotropic) {
    p[0] = std::max(p[0], 1e-7);
    p[1] = isotropic ? p[0] : std::max(p[1], 1e-7);
    if (isotropic) p[2] = p[3] = 0.0;
    return p;
}

// ∫ |f·cosθ − magnitude·D_M|^power over the sphere, estimated from n² samples of each distribution.
double fitError(const GgxLobe& lobe, const Ltc& ltc, double magnitude, int n, double power) {
    double sum = 0.0;
    auto add = [&](glm::dvec3 direction) {
        const LobeSample brdf = lobe.evaluate(direction);
        const double density = ltc.density(direction);
        const double difference = std::abs(brdf.value - magnitude * density);
        const double combined = brdf.density + density;
        if (combined > 0.0) sum += std::pow(difference, power) / combined;
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = (i + 0.5) / n, v = (j + 0.5) / n;
            add(ltc.sample(u, v));
            add(lobe.sample(u, v));
        }
    return sum / (double(n) * double(n));
}

GgxLobe lobeFor(const FitSettings& settings, int column, int row) {
    const float roughness = float(row) / float(settings.size - 1);
    const double cosTheta = double(glsl::ltcColumnCosine(uint32_t(column)));
    const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
    return {glm::dvec3(sinTheta, 0.0, cosTheta), glsl::ggxAlpha(roughness)};
}

}  // namespace

EntryFit fitEntry(const GgxLobe& lobe, const Parameters& start, bool isotropic, const FitSettings& settings) {
    EntryFit fit;
    fit.moments = lobeMoments(lobe, settings.momentSamples);
    const glm::dvec3 direction = fit.moments.direction;
    const double magnitude = fit.moments.magnitude;
    auto error = [&](const Parameters& p) {
        return fitError(lobe, Ltc(ltcMatrix(constrained(p, isotropic), direction)), magnitude, settings.errorSamples,
                        settings.errorPower);
    };
    // Steps relative to the start: near-specular entries have m00, m11 of the order of α.
    const double scale = std::max(std::abs(start[0]), 1e-6);
    const Parameters step = {0.05 * scale, 0.05 * std::max(std::abs(start[1]), 1e-6),
                             0.05 * std::max(std::abs(start[2]), scale), 0.02 * std::min(scale, 1.0)};
    fit.parameters = constrained(minimizeNelderMead<4>(error, start, step, 1e-5, settings.maxIterations), isotropic);
    fit.matrix = ltcMatrix(fit.parameters, direction);
    const Ltc ltc(fit.matrix);
    fit.relativeError = fitError(lobe, ltc, magnitude, settings.errorSamples, 1.0) / std::max(magnitude, 1e-30);
    const int n = settings.momentSamples;
    int above = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) above += ltc.sample((i + 0.5) / n, (j + 0.5) / n).z > 0.0 ? 1 : 0;
    fit.horizonShare = double(above) / (double(n) * double(n));
    return fit;
}

std::vector<EntryFit> fitTable(const FitSettings& settings, unsigned threads) {
    const int size = settings.size;
    std::vector<EntryFit> table(size_t(size) * size);
    // Normal incidence, from the roughest row (close to a plain cosine) down to the smoothest:
    // isotropic, each row starting from the one above.
    Parameters start = {1.0, 1.0, 0.0, 0.0};
    for (int row = size - 1; row >= 0; --row) {
        table[size_t(row) * size] = fitEntry(lobeFor(settings, 0, row), start, true, settings);
        start = table[size_t(row) * size].parameters;
    }
    // Then each row along the view angle, rows in parallel.
    auto fitRow = [&](int row) {
        for (int column = 1; column < size; ++column) {
            const Parameters& previous = table[size_t(row) * size + column - 1].parameters;
            table[size_t(row) * size + column] = fitEntry(lobeFor(settings, column, row), previous, false, settings);
        }
    };
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < std::max(threads, 1u); ++t)
        workers.emplace_back([&, t] {
            for (int row = int(t); row < size; row += int(std::max(threads, 1u))) fitRow(row);
        });
    for (std::thread& worker : workers) worker.join();
    return table;
}

}  // namespace vct::ltc
