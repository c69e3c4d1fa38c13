// The Pareto front of a benchmark: the settings no other setting beats on both time and error.
#pragma once

#include <cstddef>
#include <vector>

namespace vct::bench {

struct CostAndError {
    double cost = 0.0;   // e.g. milliseconds per frame; lower is better
    double error = 0.0;  // e.g. relMSE; lower is better
};

// Indices of the points on the front, ordered by rising cost (and so falling error). A point is on
// it when no other point is at least as good in both and strictly better in one. Of exact
// duplicates only the first is kept; points with a non-finite cost or error are never on it.
std::vector<size_t> paretoFront(const std::vector<CostAndError>& points);

}  // namespace vct::bench
