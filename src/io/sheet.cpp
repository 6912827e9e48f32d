#include "phongrast/io/sheet.hpp"

#include <algorithm>
#include <stdexcept>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace phongrast::io {
namespace {

// OpenImageIO's own default (DroidSans) is not packaged in Debian; DejaVuSans
// comes with fonts-dejavu-core (cmake/debian-packages.txt).
constexpr const char* label_font = "DejaVuSans";

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

    OIIO::ImageBuf sheet(OIIO::ImageSpec(sheet_columns, sheet_rows, 3, OIIO::TypeDesc::FLOAT));
    const float white[3] = {1.0f, 1.0f, 1.0f};
    OIIO::ImageBufAlgo::fill(sheet, white);
    const float black[3] = {0.0f, 0.0f, 0.0f};

    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int grid_x = static_cast<int>(i) % grid_columns;
        const int grid_y = static_cast<int>(i) / grid_columns;
        const int left = gap + grid_x * (cell_columns + gap);
        const int top = gap + grid_y * (label_height + cell_rows + gap);
        const OIIO::ImageSpec cell_spec(cell_columns, cell_rows, 3, OIIO::TypeDesc::FLOAT);
        // ImageBuf wraps the pixels without copying; glm::vec3 is three packed floats.
        OIIO::ImageBuf cell(cell_spec, const_cast<glm::vec3*>(cells[i].image.pixels.data()));
        if (!OIIO::ImageBufAlgo::paste(sheet, left, top + label_height, 0, 0, cell)) {
            throw std::runtime_error("compose_sheet: " + sheet.geterror());
        }
        if (!cells[i].label.empty() &&
            !OIIO::ImageBufAlgo::render_text(sheet, left + 2, top + font_size + 2, cells[i].label, font_size,
                                             label_font, black)) {
            throw std::runtime_error("compose_sheet: cannot draw the label '" + cells[i].label + "' with font " +
                                     label_font + " (Debian package fonts-dejavu-core): " + sheet.geterror());
        }
    }

    Image result(sheet_rows, sheet_columns);
    if (!sheet.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, result.pixels.data())) {
        throw std::runtime_error("compose_sheet: " + sheet.geterror());
    }
    return result;
}

}  // namespace phongrast::io
