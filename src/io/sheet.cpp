#include "phongrast/io/sheet.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "text_drawing.hpp"

namespace phongrast::io {
namespace {

// fonts-dejavu-core (cmake/debian-packages.txt) provides it.
constexpr const char* label_font_family = "DejaVu Sans";
constexpr const char* label_font_package = "fonts-dejavu-core";

// Found once per process: fontconfig reads its configuration and caches on each lookup.
const std::string& label_font_file() {
    static const std::string file = detail::font_file_for(label_font_family, label_font_package);
    return file;
}

}  // namespace

Image compose_sheet(const std::vector<SheetCell>& cells, int columns) {
    if (cells.empty()) throw std::invalid_argument("compose_sheet: no images");
    if (columns < 1) throw std::invalid_argument("compose_sheet: columns must be at least 1");
    const int cell_rows = cells.front().image.rows;
    const int cell_columns = cells.front().image.columns;
    for (const SheetCell& cell : cells) {
        validate_image(cell.image);  // a short pixel buffer would be read past its end
        if (cell.image.rows != cell_rows || cell.image.columns != cell_columns) {
            throw std::invalid_argument("compose_sheet: every image must have the same size");
        }
    }
    const int grid_columns = std::min<int>(columns, static_cast<int>(cells.size()));
    const int grid_rows = (static_cast<int>(cells.size()) + grid_columns - 1) / grid_columns;
    const int font_size = std::max(12, std::min(cell_columns, cell_rows * 2) / 14);
    const int label_height = font_size * 3 / 2 + 4;
    const int gap = std::max(4, font_size / 2);
    const int sheet_columns = gap + grid_columns * (cell_columns + gap);
    const int sheet_rows = gap + grid_rows * (label_height + cell_rows + gap);

    // White, then each cell copied below its label strip and its label drawn.
    Image sheet(sheet_rows, sheet_columns, glm::vec3(1.0f));
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int grid_x = static_cast<int>(i) % grid_columns;
        const int grid_y = static_cast<int>(i) / grid_columns;
        const int left = gap + grid_x * (cell_columns + gap);
        const int top = gap + grid_y * (label_height + cell_rows + gap);
        for (int row = 0; row < cell_rows; ++row) {
            const glm::vec3* from = &cells[i].image.at(row, 0);
            std::copy(from, from + cell_columns, &sheet.at(top + label_height + row, left));
        }
        if (cells[i].label.empty()) continue;
        try {
            detail::draw_text(sheet, left + 2, top + font_size + 2, cells[i].label, font_size, label_font_file(),
                              glm::vec3(0.0f));
        } catch (const std::runtime_error& failure) {
            throw std::runtime_error("compose_sheet: cannot draw the label '" + cells[i].label + "': " + failure.what());
        }
    }
    return sheet;
}

}  // namespace phongrast::io
