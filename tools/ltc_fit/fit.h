// Fitting the GGX lobe with a linearly transformed cosine, one table entry at a time (Heitz et
// al. 2016, §4): M = [X Y Z]·[[m00 0 m02] [0 m11 0] [0 0 1]] with Y the normal of the plane of
// incidence and Z the lobe's mean direction turned by an angle in that plane; m00, m11, m02 and the
// angle minimise ∫ |f·cosθ − magnitude·D_M|^0.75 by Nelder–Mead, sampled from both distributions
// (balance heuristic). Two departures from the paper's code, measured on lights integrated against
// the BRDF (tests/cpu/ltc_test.cpp, metal: RMS relative error) and on a glossy floor under a lamp
// against the path tracer (relMSE of the image):
//  - freeing Z from the mean direction (a fourth parameter): 0.16 → 0.094, and the table's mean
//    relative L1 error of the lobe 0.14 → 0.09;
//  - a lower power of the error than the paper's cube, which fits the peak at the expense of the
//    tail: the floor seen at grazing angles, where a lamp behind the viewer lights only the lobe's
//    tail, was up to 7× too bright with the cube (relMSE 0.14); the power 1 gave 0.056 and 0.085,
//    0.75 gives 0.067 and 0.014, 0.5 0.087 and 0.021 (and 30–40 % off in the mirror direction).
#pragma once

#include <array>
#include <vector>

#include "ggx_lobe.h"
#include "ltc.h"

namespace vct::ltc {

using Parameters = std::array<double, 4>;  // m00, m11, m02, the angle from the mean direction

struct EntryFit {
    Parameters parameters;
    LobeMoments moments;
    glm::dmat3 matrix;     // M
    double relativeError;  // ∫ |f·cosθ − magnitude·D_M| / magnitude
    double horizonShare;   // ∫ D_M above the surface's horizon (the rest is lost to clipping)
};

struct FitSettings {
    int size = int(glsl::LTC_TABLE_SIZE);  // entries along roughness and along the view angle
    int errorSamples = 32;                 // n² samples from each distribution for the fit's error
    int momentSamples = 128;               // n² samples for magnitude, fresnel and the mean direction
    int maxIterations = 200;               // of Nelder–Mead, per entry
    double errorPower = 0.75;              // of |f·cosθ − magnitude·D_M| in the fit's error
};

EntryFit fitEntry(const GgxLobe& lobe, const Parameters& start, bool isotropic, const FitSettings& settings);

// The whole table, row (roughness) by row, entry y · size + x (x along sqrt(1 − cosθ)). Each row
// starts from the normal-incidence fit of the row rougher than it and continues along the view
// angle from its neighbour, so the result does not depend on `threads`.
std::vector<EntryFit> fitTable(const FitSettings& settings, unsigned threads);

}  // namespace vct::ltc
