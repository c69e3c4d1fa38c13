// Nelder–Mead's downhill simplex (Nelder and Mead 1965) with the usual coefficients: reflection 1,
// expansion 2, contraction ½, shrink ½. Deterministic; stops when the simplex's values agree to a
// relative tolerance or after a number of iterations.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace vct::ltc {

template <int N, typename Function>
std::array<double, N> minimizeNelderMead(Function f, const std::array<double, N>& start,
                                         const std::array<double, N>& step, double tolerance, int maxIterations) {
    using Point = std::array<double, N>;
    std::array<Point, N + 1> points;
    std::array<double, N + 1> values;
    for (int i = 0; i <= N; ++i) {
        points[i] = start;
        if (i > 0) points[i][i - 1] += step[i - 1];
        values[i] = f(points[i]);
    }
    auto along = [](const Point& from, const Point& to, double t) {
        Point p;
        for (int k = 0; k < N; ++k) p[k] = from[k] + (to[k] - from[k]) * t;
        return p;
    };
    for (int iteration = 0; iteration < maxIterations; ++iteration) {
        std::array<int, N + 1> order;
        for (int i = 0; i <= N; ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](int a, int b) { return values[a] < values[b]; });
        const int best = order[0], worst = order[N], secondWorst = order[N - 1];
        if (std::abs(values[worst] - values[best]) <= tolerance * (std::abs(values[best]) + 1e-30)) break;
        Point centroid{};
        for (int i = 0; i <= N; ++i)
            if (i != worst)
                for (int k = 0; k < N; ++k) centroid[k] += points[i][k] / N;
        const Point reflected = along(points[worst], centroid, 2.0);
        const double reflectedValue = f(reflected);
        if (reflectedValue < values[best]) {
            const Point expanded = along(points[worst], centroid, 3.0);
            const double expandedValue = f(expanded);
            if (expandedValue < reflectedValue) {
                points[worst] = expanded, values[worst] = expandedValue;
            } else {
                points[worst] = reflected, values[worst] = reflectedValue;
            }
            continue;
        }
        if (reflectedValue < values[secondWorst]) {
            points[worst] = reflected, values[worst] = reflectedValue;
            continue;
        }
        // Contract towards the better of the worst point and its reflection.
        const bool outside = reflectedValue < values[worst];
        const Point contracted = outside ? along(points[worst], centroid, 1.5) : along(points[worst], centroid, 0.5);
        const double contractedValue = f(contracted);
        if (contractedValue < std::min(reflectedValue, values[worst])) {
            points[worst] = contracted, values[worst] = contractedValue;
            continue;
        }
        for (int i = 0; i <= N; ++i)
            if (i != best) {
                points[i] = along(points[best], points[i], 0.5);
                values[i] = f(points[i]);
            }
    }
    int best = 0;
    for (int i = 1; i <= N; ++i)
        if (values[i] < values[best]) best = i;
    return points[best];
}

}  // namespace vct::ltc
