#include "pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "support/image_compare.hpp"

namespace phongrast_bench {
namespace {

namespace OIIO = OIIO_NAMESPACE;
using OIIO::ImageBuf;
using OIIO::ImageBufAlgo::TextAlignX;
using OIIO::ImageBufAlgo::TextAlignY;

// Installed with fonts-dejavu-core; OpenImageIO's own default (DroidSans) is not.
const char* const kFont = "DejaVuSans";

struct Color {
    float r, g, b;
};
const Color kBlack{0, 0, 0}, kGrid{0.88f, 0.88f, 0.88f}, kScreened{0.72f, 0.72f, 0.72f},
    kSeed{0.9f, 0.45f, 0.0f}, kExact{0.1f, 0.35f, 0.85f}, kFront{0.75f, 0.0f, 0.15f};

void text(ImageBuf& buf, int x, int y, const std::string& s, int size, Color c,
          TextAlignX ax = TextAlignX::Left, TextAlignY ay = TextAlignY::Baseline) {
    const float color[3] = {c.r, c.g, c.b};
    if (!OIIO::ImageBufAlgo::render_text(buf, x, y, s, size, kFont, color, ax, ay)) {
        throw std::runtime_error("render_text with font " + std::string(kFont) + ": " + buf.geterror());
    }
}

void line(ImageBuf& buf, int x0, int y0, int x1, int y1, Color c) {
    const float color[3] = {c.r, c.g, c.b};
    OIIO::ImageBufAlgo::render_line(buf, x0, y0, x1, y1, color);
}

void box(ImageBuf& buf, int x, int y, int half, Color c, bool filled = true) {
    const float color[3] = {c.r, c.g, c.b};
    OIIO::ImageBufAlgo::render_box(buf, x - half, y - half, x + half, y + half, color, filled);
}

void save(ImageBuf& buf, const std::string& path) {
    // Written next to the target and renamed, so a failure leaves no partial file.
    const std::string temporary = path + ".tmp.png";
    if (!buf.write(temporary)) throw std::runtime_error(path + ": " + buf.geterror());
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        throw std::runtime_error(path + ": could not rename the written file into place");
    }
}

/// An RGB float buffer of rows x columns pixels, row-major.
void save_rgb(const std::string& path, int rows, int columns, const std::vector<float>& rgb) {
    ImageBuf buf(OIIO::ImageSpec(columns, rows, 3, OIIO::TypeDesc::FLOAT), const_cast<float*>(rgb.data()));
    ImageBuf copy;
    copy.copy(buf, OIIO::TypeDesc::UINT8);
    save(copy, path);
}

float clamp01(float value) { return std::clamp(value, 0.0f, 1.0f); }

std::string decade_label(int exponent, const char* unit) {
    char buffer[32];
    if (exponent >= 0 && exponent <= 3) {
        std::snprintf(buffer, sizeof buffer, "%g%s", std::pow(10.0, exponent), unit);
    } else if (exponent < 0 && exponent >= -2) {
        std::snprintf(buffer, sizeof buffer, "%g%s", std::pow(10.0, exponent), unit);
    } else {
        std::snprintf(buffer, sizeof buffer, "1e%d%s", exponent, unit);
    }
    return buffer;
}

/// "hot": black below one 8-bit level, then red, yellow, white at 0.5 and above (log scale).
Color heat(double error) {
    if (error <= 1.0 / 255.0) return {0, 0, 0};
    const double t = std::clamp(std::log(error * 255.0) / std::log(0.5 * 255.0), 0.0, 1.0);
    const auto ramp = [t](double start) { return static_cast<float>(std::clamp(3.0 * t - start, 0.0, 1.0)); };
    return {std::max(0.25f, ramp(0.0)), ramp(1.0), ramp(2.0)};
}

}  // namespace

void write_error_time_plot(const std::string& path, const std::string& title,
                           const std::vector<PlotPoint>& points, const std::vector<std::size_t>& front) {
    // Tall enough for the list of the front's configurations beside the plot.
    const int width = 1250, left = 90, right = 350, top = 60, bottom = 70;
    const int height = std::max(600, top + 17 * static_cast<int>(front.size() + 1) + 30);
    ImageBuf buf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    const float white[3] = {1, 1, 1};
    OIIO::ImageBufAlgo::fill(buf, white);

    double min_ms = 1e300, max_ms = 0, min_e = 1e300, max_e = 0;
    for (const PlotPoint& p : points) {
        min_ms = std::min(min_ms, p.milliseconds);
        max_ms = std::max(max_ms, p.milliseconds);
        if (p.rmse > 0) min_e = std::min(min_e, p.rmse);
        max_e = std::max(max_e, p.rmse);
    }
    if (points.empty() || max_e <= 0) return;
    // An error of exactly zero cannot sit on a log axis: drawn on the bottom edge.
    const int x_lo = static_cast<int>(std::floor(std::log10(min_ms))), x_hi = static_cast<int>(std::ceil(std::log10(max_ms)));
    const int y_lo = static_cast<int>(std::floor(std::log10(min_e))), y_hi = static_cast<int>(std::ceil(std::log10(max_e)));
    const int x_span = std::max(1, x_hi - x_lo), y_span = std::max(1, y_hi - y_lo);
    const auto px = [&](double ms) {
        return left + static_cast<int>((std::log10(ms) - x_lo) / x_span * (width - left - right));
    };
    const auto py = [&](double e) {
        const double l = e > 0 ? std::log10(e) : double(y_lo);
        return height - bottom - static_cast<int>((l - y_lo) / y_span * (height - top - bottom));
    };

    for (int d = x_lo; d <= x_lo + x_span; ++d) {
        line(buf, px(std::pow(10.0, d)), top, px(std::pow(10.0, d)), height - bottom, kGrid);
        text(buf, px(std::pow(10.0, d)), height - bottom + 22, decade_label(d, " ms"), 15, kBlack, TextAlignX::Center);
    }
    for (int d = y_lo; d <= y_lo + y_span; ++d) {
        line(buf, left, py(std::pow(10.0, d)), width - right, py(std::pow(10.0, d)), kGrid);
        text(buf, left - 8, py(std::pow(10.0, d)), decade_label(d, ""), 15, kBlack, TextAlignX::Right,
             TextAlignY::Center);
    }
    line(buf, left, top, left, height - bottom, kBlack);
    line(buf, left, height - bottom, width - right, height - bottom, kBlack);
    text(buf, (left + width - right) / 2, height - 18, "median time of one render, 1 thread (log)", 16, kBlack,
         TextAlignX::Center);
    text(buf, 12, top - 14, "RMSE vs reference (log)", 16, kBlack);
    text(buf, left, 26, title, 19, kBlack);

    for (const PlotPoint& p : points) {
        if (p.kind == PointKind::screened) box(buf, px(p.milliseconds), py(p.rmse), 1, kScreened);
    }
    for (std::size_t k = 1; k < front.size(); ++k) {
        const PlotPoint& a = points[front[k - 1]];
        const PlotPoint& b = points[front[k]];
        line(buf, px(a.milliseconds), py(a.rmse), px(b.milliseconds), py(b.rmse), kFront);
    }
    for (const PlotPoint& p : points) {
        if (p.kind == PointKind::screened) continue;
        const Color c = p.kind == PointKind::from_seed ? kSeed : p.kind == PointKind::from_exact ? kExact : kFront;
        box(buf, px(p.milliseconds), py(p.rmse), 3, c);
    }
    // The front's points are numbered (alternately above and below the line, so
    // neighbours do not overlap) and listed with their configurations on the right.
    std::vector<bool> on_front(points.size(), false);
    for (std::size_t k = 0; k < front.size(); ++k) {
        const PlotPoint& p = points[front[k]];
        on_front[front[k]] = true;
        text(buf, px(p.milliseconds) + 6, py(p.rmse) + (k % 2 ? 17 : -7), std::to_string(k + 1), 12, kFront);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const PlotPoint& p = points[i];
        if (p.kind == PointKind::screened || p.label.empty() || on_front[i]) continue;
        const Color c = p.kind == PointKind::from_seed ? kSeed : kExact;
        text(buf, px(p.milliseconds) + 7, py(p.rmse) - 6, p.label, 12, c);
    }
    int list_y = top + 14;
    text(buf, width - right + 14, list_y, "Pareto front, fastest first:", 13, kBlack);
    for (std::size_t k = 0; k < front.size(); ++k) {
        list_y += 17;
        const std::string& label = points[front[k]].label;
        text(buf, width - right + 14, list_y, std::to_string(k + 1) + "  " + (label.empty() ? "?" : label), 11, kFront);
    }
    for (std::size_t index : front) box(buf, px(points[index].milliseconds), py(points[index].rmse), 5, kFront, false);

    // Legend.
    int y = top + 14;
    const auto legend = [&](Color c, const std::string& s, int half) {
        box(buf, width - right - 330, y - 5, half, c);
        text(buf, width - right - 318, y, s, 13, kBlack);
        y += 18;
    };
    legend(kSeed, "seed, and one option switched from it", 3);
    legend(kExact, "exact, and one option switched from it", 3);
    legend(kScreened, "every combination (one unwarmed run each)", 1);
    legend(kFront, "Pareto front (line; numbered, named on the right)", 3);
    save(buf, path);
}

void write_panels(const std::string& path, const std::vector<Panel>& panels) {
    if (panels.empty()) return;
    const int cell_w = panels[0].image.columns, cell_h = panels[0].image.rows, gap = 6, caption = 24, legend = 34;
    const int n = static_cast<int>(panels.size());
    const int per_row = std::min(n, 4), panel_rows = (n + per_row - 1) / per_row;
    const int width = per_row * cell_w + (per_row + 1) * gap, height = panel_rows * (caption + cell_h) + gap + legend;
    ImageBuf buf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    const float white[3] = {1, 1, 1};
    OIIO::ImageBufAlgo::fill(buf, white);
    for (int k = 0; k < n; ++k) {
        const Panel& panel = panels[k];
        const int x0 = gap + (k % per_row) * (cell_w + gap), y0 = (k / per_row) * (caption + cell_h) + caption;
        for (int row = 0; row < panel.image.rows && row < cell_h; ++row) {
            for (int column = 0; column < panel.image.columns && column < cell_w; ++column) {
                float rgb[3];
                if (panel.errors.empty()) {
                    const glm::vec3& v = panel.image.at(row, column);
                    for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(v[c], 0.0f, 1.0f);
                } else {
                    const Color h = heat(panel.errors[static_cast<std::size_t>(row) * panel.image.columns + column]);
                    rgb[0] = h.r, rgb[1] = h.g, rgb[2] = h.b;
                }
                buf.setpixel(x0 + column, y0 + row, rgb, 3);
            }
        }
        text(buf, x0 + cell_w / 2, y0 - 7, panel.caption, 14, kBlack, TextAlignX::Center);
    }
    // Heat legend: the colour of errors from 1/255 to 0.5.
    const int bar_x = gap, bar_w = std::min(width - 2 * gap - 330, 400), bar_y = panel_rows * (caption + cell_h) + gap + 4;
    for (int x = 0; x < bar_w; ++x) {
        const double e = std::exp(std::log(1.0 / 255.0) + (std::log(0.5) - std::log(1.0 / 255.0)) * x / (bar_w - 1));
        const Color c = heat(e * 1.0001);
        line(buf, bar_x + x, bar_y, bar_x + x, bar_y + 10, c);
    }
    text(buf, bar_x, bar_y + 26, "1/255", 12, kBlack);
    text(buf, bar_x + bar_w, bar_y + 26, "0.5 (log scale; black: within one 8-bit level)", 12, kBlack);
    save(buf, path);
}

void write_png(const std::string& path, const phongrast::Image& image) {
    std::vector<float> rgb;
    rgb.reserve(image.pixels.size() * 3);
    for (const glm::vec3& p : image.pixels) rgb.insert(rgb.end(), {clamp01(p.x), clamp01(p.y), clamp01(p.z)});
    save_rgb(path, image.rows, image.columns, rgb);
}

void write_difference_map(const std::string& path, const phongrast::Image& first, const phongrast::Image& second,
                          const glm::vec3& background) {
    const std::vector<double> map = phongrast::support::error_map(first, second);
    std::vector<float> rgb;
    rgb.reserve(map.size() * 3);
    for (std::size_t i = 0; i < map.size(); ++i) {
        const bool in_first = first.pixels[i] != background;
        const bool in_second = second.pixels[i] != background;
        glm::vec3 colour(0.0f);
        if (in_first && !in_second) {
            colour = {1.0f, 0.0f, 1.0f};
        } else if (!in_first && in_second) {
            colour = {0.0f, 1.0f, 1.0f};
        } else if (map[i] > phongrast::support::kOneLevel) {
            const float t = std::min(1.0f, float(map[i] / (16.0 * phongrast::support::kOneLevel)));
            colour = {clamp01(3.0f * t), clamp01(3.0f * t - 1.0f), clamp01(3.0f * t - 2.0f)};
            colour.x = std::max(colour.x, 0.35f);  // even 2/255 stays visible
        } else if (in_first) {
            colour = glm::vec3(0.15f);
        }
        rgb.insert(rgb.end(), {colour.x, colour.y, colour.z});
    }
    save_rgb(path, first.rows, first.columns, rgb);
}

}  // namespace phongrast_bench
