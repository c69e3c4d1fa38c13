#include "bench/pareto.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vct::bench {

std::vector<size_t> paretoFront(const std::vector<CostAndError>& points) {
    std::vector<size_t> order;
    for (size_t i = 0; i < points.size(); ++i)
        if (std::isfinite(points[i].cost) && std::isfinite(points[i].error)) order.push_back(i);
    // By cost, then error, then index: a sweep keeps each point that lowers the best error so far.
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
        if (points[a].error != points[b].error) return points[a].error < points[b].error;
        return a < b;
    });
    std::vector<size_t> front;
    double bestError = std::numeric_limits<double>::infinity();
    for (size_t index : order) {
        if (points[index].error < bestError) {
            front.push_back(index);
            bestError = points[index].error;
        }
    }
    return front;
}

}  // namespace vct::bench
