// How far a rendered image is from its path-traced reference, in the numbers `vct bench` reports.
//
// All four are computed on linear radiance. relMSE and RMSE use every channel; the luminance ratio
// and the share of pixels off use Rec. 709 luminance per pixel.
#pragma once

#include <cstddef>

#include "io/image_io.h"

namespace vct::bench {

// Tolerances as data, so a reader finds them in one place.
struct MetricTolerances {
    // relMSE's ε, as a fraction of the reference's mean channel value m: the denominator is
    // r² + (relativeEpsilon · m)². Scaling both images by the same factor leaves relMSE as it is,
    // and pixels far darker than the image (black walls, the sky) cannot dominate it.
    double relativeEpsilon = 0.1;
    // A pixel is "off" when |L − L_ref| > offFraction · L_ref + offFloor · mean(L_ref):
    // 10 % of its own luminance, plus a floor of 1 % of the image's mean so black pixels with a
    // little noise do not count.
    double offFraction = 0.10;
    double offFloor = 0.01;
};

struct ImageError {
    double relMse = 0.0;          // mean over channels of (x − r)² / (r² + ε)
    double rmse = 0.0;            // sqrt(mean over channels of (x − r)²), in radiance units
    double luminanceRatio = 0.0;  // mean luminance of the image / that of the reference (1 = right)
    double shareOff = 0.0;        // share of pixels off by more than the tolerance, 0..1
};

// Throws vct::Error when the sizes differ. A reference that is black everywhere gives a luminance
// ratio of 1 when the image is black too, and infinity otherwise.
ImageError compareImages(const Image& image, const Image& reference, const MetricTolerances& tolerances = {});

// Indirect light where it is all there is: its luminance over the pixels that the reference's direct
// light leaves in shadow (under `shadowFraction` × that light's mean over the image), against the
// reference's indirect light there. Shadows are where a viewer judges indirect light (the blocks'
// shadowed faces in the Cornell box), and where a whole image's ratio hides errors: a box whose lit
// walls are too bright and whose shadows too dark averages out. NaN where no pixel is in shadow or
// the reference's indirect light there is black. Throws vct::Error when the sizes differ.
double shadowedLuminanceRatio(const Image& indirect, const Image& referenceIndirect, const Image& referenceDirect,
                              double shadowFraction = 0.1);

// a + b, pixel by pixel (the full reference is direct + indirect). Sizes must agree.
Image addImages(const Image& a, const Image& b);

}  // namespace vct::bench
