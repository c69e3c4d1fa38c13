#include "bench/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace vct::bench {
namespace {

// The plot area and its margins; the key from point numbers to settings goes right of it, as wide
// and as tall as its lines need.
constexpr double kPlotWidth = 740, kPlotHeight = 460;
constexpr double kLeft = 90, kTop = 70, kBottom = 70;
constexpr double kKeyGap = 20, kKeyRightMargin = 16, kKeyLine = 16;

// A logarithmic axis spanning whole decades around [lo, hi].
struct LogAxis {
    double lowDecade = 0, highDecade = 1;
    LogAxis(double lo, double hi) {
        lowDecade = std::floor(std::log10(lo));
        highDecade = std::ceil(std::log10(hi));
        if (highDecade <= lowDecade) highDecade = lowDecade + 1;
    }
    double fraction(double value) const { return (std::log10(value) - lowDecade) / (highDecade - lowDecade); }
};

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, std::fabs(value) >= 1e4 && std::fabs(value) < 1e9 ? "%.0f" : "%.4g", value);
    return text;
}

}  // namespace

double estimatedTextWidth(const std::string& text) {
    size_t characters = 0;
    for (unsigned char c : text) characters += (c & 0xC0) != 0x80;  // UTF-8: count lead bytes only
    return 12.0 * 0.62 * double(characters);
}

std::string escapeXml(const std::string& text) {
    std::string escaped;
    for (char c : text) {
        if (c == '&') escaped += "&amp;";
        else if (c == '<') escaped += "&lt;";
        else if (c == '>') escaped += "&gt;";
        else if (c == '"') escaped += "&quot;";
        else escaped += c;
    }
    return escaped;
}

std::string plotErrorAgainstTime(const std::vector<PlotPoint>& allPoints, const PlotText& text) {
    std::vector<PlotPoint> points;
    for (const PlotPoint& p : allPoints)
        if (std::isfinite(p.x) && std::isfinite(p.y) && p.x > 0 && p.y > 0) points.push_back(p);
    double xLo = 1, xHi = 10, yLo = 0.01, yHi = 1;
    if (!points.empty()) {
        xLo = xHi = points[0].x;
        yLo = yHi = points[0].y;
        for (const PlotPoint& p : points) {
            xLo = std::min(xLo, p.x), xHi = std::max(xHi, p.x);
            yLo = std::min(yLo, p.y), yHi = std::max(yHi, p.y);
        }
    }
    const LogAxis xAxis(xLo, xHi), yAxis(yLo, yHi);
    const double plotWidth = kPlotWidth, plotHeight = kPlotHeight;
    std::vector<std::string> keyLines;
    for (size_t i = 0; i < points.size(); ++i) {
        const PlotPoint& p = points[i];
        keyLines.push_back(std::to_string(i + 1) + "  " + p.label + (p.preset.empty() ? "" : "  (" + p.preset + ")") +
                           (p.onFront ? "  *" : ""));
    }
    double keyWidth = estimatedTextWidth("key");
    for (size_t i = 0; i < keyLines.size(); ++i)  // a preset's line is bold, about a tenth wider
        keyWidth = std::max(keyWidth, estimatedTextWidth(keyLines[i]) * (points[i].preset.empty() ? 1.0 : 1.1));
    for (const std::string& line : text.keyNotes) keyWidth = std::max(keyWidth, estimatedTextWidth(line));
    const double keyX = kLeft + plotWidth + kKeyGap;
    const double keyNotesY = kTop + 22 + kKeyLine * (double(keyLines.size()) + 1);
    const double width = std::ceil(keyX + keyWidth + kKeyRightMargin);
    const double height =
        std::ceil(std::max(kTop + plotHeight + kBottom, keyNotesY + kKeyLine * double(text.keyNotes.size()) + 8));
    const auto px = [&](double x) { return kLeft + xAxis.fraction(x) * plotWidth; };
    const auto py = [&](double y) { return kTop + (1.0 - yAxis.fraction(y)) * plotHeight; };

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << width / 2 << "\" y=\"24\" text-anchor=\"middle\" font-size=\"16\">" << escapeXml(text.title)
        << "</text>\n<text x=\"" << width / 2 << "\" y=\"44\" text-anchor=\"middle\" fill=\"#555\">"
        << escapeXml(text.note) << "</text>\n";

    // Grid lines at 1, 2 and 5 × each decade; labels at the decades and, on short axes, the 2s and 5s.
    const auto gridLines = [&](const LogAxis& axis, bool horizontal) {
        const bool labelAll = axis.highDecade - axis.lowDecade <= 2;
        for (double decade = axis.lowDecade; decade <= axis.highDecade; ++decade) {
            for (double step : {1.0, 2.0, 5.0}) {
                const double value = step * std::pow(10.0, decade);
                if (axis.fraction(value) > 1.0 + 1e-9) continue;
                const bool major = step == 1.0;
                const double at = horizontal ? py(value) : px(value);
                svg << "<line "
                    << (horizontal ? "x1=\"" + number(kLeft) + "\" x2=\"" + number(kLeft + plotWidth) + "\" y1=\"" +
                                         number(at) + "\" y2=\"" + number(at)
                                   : "y1=\"" + number(kTop) + "\" y2=\"" + number(kTop + plotHeight) + "\" x1=\"" +
                                         number(at) + "\" x2=\"" + number(at))
                    << "\" stroke=\"" << (major ? "#bbb" : "#e4e4e4") << "\"/>\n";
                if (!major && !labelAll) continue;
                if (horizontal)
                    svg << "<text x=\"" << kLeft - 6 << "\" y=\"" << at + 4 << "\" text-anchor=\"end\">"
                        << number(value) << "</text>\n";
                else
                    svg << "<text x=\"" << at << "\" y=\"" << kTop + plotHeight + 18 << "\" text-anchor=\"middle\">"
                        << number(value) << "</text>\n";
            }
        }
    };
    gridLines(xAxis, false);
    gridLines(yAxis, true);
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << plotWidth << "\" height=\"" << plotHeight
        << "\" fill=\"none\" stroke=\"#333\"/>\n"
        << "<text x=\"" << kLeft + plotWidth / 2 << "\" y=\"" << kTop + plotHeight + kBottom - 24
        << "\" text-anchor=\"middle\">" << escapeXml(text.xLabel) << "</text>\n"
        << "<text transform=\"translate(22," << kTop + plotHeight / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
        << escapeXml(text.yLabel) << "</text>\n";

    // The front as a staircase: from each front point, right to the next one's cost, then down.
    std::vector<const PlotPoint*> front;
    for (const PlotPoint& p : points)
        if (p.onFront) front.push_back(&p);
    std::sort(front.begin(), front.end(), [](const PlotPoint* a, const PlotPoint* b) { return a->x < b->x; });
    if (!front.empty()) {
        svg << "<polyline fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\" points=\"";
        for (size_t i = 0; i < front.size(); ++i) {
            svg << number(px(front[i]->x)) << "," << number(py(front[i]->y)) << " ";
            if (i + 1 < front.size()) svg << number(px(front[i + 1]->x)) << "," << number(py(front[i]->y)) << " ";
        }
        svg << "\"/>\n";
    }

    // Each point carries its number; the key beside the plot names the setting, so labels of
    // neighbouring points cannot hide each other.
    svg << "<text x=\"" << keyX << "\" y=\"" << kTop + 4 << "\" font-weight=\"bold\">key</text>\n";
    for (size_t i = 0; i < points.size(); ++i) {
        const PlotPoint& p = points[i];
        const bool preset = !p.preset.empty();
        const std::string fill = preset ? "#1f77b4" : p.onFront ? "#d62728" : "#888";
        const std::string stroke = p.onFront ? "#d62728" : "black";
        const std::string id = std::to_string(i + 1);
        svg << "<g><title>" << escapeXml(p.label) << ": " << number(p.x) << ", " << number(p.y)
            << "</title><circle cx=\"" << number(px(p.x)) << "\" cy=\"" << number(py(p.y)) << "\" r=\""
            << (preset ? 7 : 4) << "\" fill=\"" << fill << "\""
            << (preset ? " stroke=\"" + stroke + "\" stroke-width=\"2\"" : "") << "/></g>\n";
        svg << "<text x=\"" << number(px(p.x) + (preset ? 9 : 6)) << "\" y=\"" << number(py(p.y) - 5)
            << "\" font-size=\"" << (preset ? 13 : 11) << "\" fill=\"" << (preset ? "#1f77b4" : "#444") << "\""
            << (preset ? " font-weight=\"bold\"" : "") << ">" << escapeXml(preset ? id + " " + p.preset : id)
            << "</text>\n";
        svg << "<text x=\"" << keyX << "\" y=\"" << kTop + 22 + 16 * double(i) << "\" fill=\""
            << (preset      ? "#1f77b4"
                : p.onFront ? "#d62728"
                            : "#444")
            << "\"" << (preset ? " font-weight=\"bold\"" : "") << ">" << escapeXml(keyLines[i]) << "</text>\n";
    }
    for (size_t i = 0; i < text.keyNotes.size(); ++i)
        svg << "<text x=\"" << keyX << "\" y=\"" << keyNotesY + kKeyLine * double(i) << "\" fill=\"#555\">"
            << escapeXml(text.keyNotes[i]) << "</text>\n";

    // Legend, in the plot's top right corner.
    const double lx = kLeft + plotWidth - 200, ly = kTop + 12;
    svg << "<rect x=\"" << lx - 8 << "\" y=\"" << ly - 12 << "\" width=\"200\" height=\"58\" fill=\"white\" "
        << "stroke=\"#999\"/>\n"
        << "<circle cx=\"" << lx << "\" cy=\"" << ly << "\" r=\"4\" fill=\"#888\"/><text x=\"" << lx + 10 << "\" y=\""
        << ly + 4 << "\">setting</text>\n"
        << "<circle cx=\"" << lx << "\" cy=\"" << ly + 17 << "\" r=\"4\" fill=\"#d62728\"/><text x=\"" << lx + 10
        << "\" y=\"" << ly + 21 << "\">on the Pareto front (*)</text>\n"
        << "<circle cx=\"" << lx << "\" cy=\"" << ly + 34 << "\" r=\"6\" fill=\"#1f77b4\" stroke=\"#d62728\" "
        << "stroke-width=\"2\"/><text x=\"" << lx + 10 << "\" y=\"" << ly + 38
        << "\">preset (red ring: on the front)</text>\n"
        << "</svg>\n";
    return svg.str();
}

}  // namespace vct::bench
