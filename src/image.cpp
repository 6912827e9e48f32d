// Image's checks and the shared image-size limit (include/phongrast/image.hpp).
#include <stdexcept>
#include <string>

#include "image_size.hpp"
#include "phongrast/image.hpp"

namespace phongrast {
namespace detail {

std::string memory_text(double bytes) {
    char text[48];
    if (bytes >= 1024.0 * 1024.0 * 1024.0) {
        std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    } else {
        std::snprintf(text, sizeof text, "%.1f MiB", bytes / (1024.0 * 1024.0));
    }
    return text;
}

std::string image_limit_text(const char* unit) {
    return "at most " + std::to_string(kMaxImagePixels) + " " + unit + " (" +
           memory_text(double(kMaxImagePixels) * double(kImageBytesPerPixel)) + " as float RGB)";
}

void throw_pixel_out_of_range(int row, int column, int rows, int columns, std::size_t pixels) {
    std::string message = "Image::at(" + std::to_string(row) + ", " + std::to_string(column) + "): ";
    if (row < 0 || row >= rows || column < 0 || column >= columns) {
        message += "outside the image (image.rows = " + std::to_string(rows) +
                   ", image.columns = " + std::to_string(columns) + ")";
    } else {
        message += "image.pixels.size() is " + std::to_string(pixels) + ", expected image.rows * image.columns = " +
                   std::to_string(static_cast<long long>(rows) * columns);
    }
    throw std::out_of_range(message);
}

void check_image_allocation(int rows, int columns) {
    if (rows < 0 || columns < 0) {
        throw std::invalid_argument("Image(" + std::to_string(rows) + ", " + std::to_string(columns) +
                                    "): rows and columns must not be negative");
    }
    if (rows > 0 && columns > 0) validate_image_size(rows, columns);
}

}  // namespace detail

void validate_image_size(std::int64_t rows, std::int64_t columns, const char* rows_name, const char* columns_name) {
    if (rows < 1) {
        throw std::invalid_argument(std::string(rows_name) + ": expected 1 to " + std::to_string(kMaxImageSide) +
                                    " rows, got " + std::to_string(rows));
    }
    if (columns < 1) {
        throw std::invalid_argument(std::string(columns_name) + ": expected 1 to " + std::to_string(kMaxImageSide) +
                                    " columns, got " + std::to_string(columns));
    }
    const double pixels = double(rows) * double(columns);
    if (rows > kMaxImageSide || columns > kMaxImageSide || pixels > double(kMaxImagePixels)) {
        throw std::length_error(std::string(rows_name) + " x " + columns_name + ": " + std::to_string(rows) + " x " +
                                std::to_string(columns) + " pixels would take " +
                                detail::memory_text(pixels * double(kImageBytesPerPixel)) +
                                " as float RGB; expected at most " + std::to_string(kMaxImageSide) + " a side and " +
                                detail::image_limit_text("pixels"));
    }
}

void validate_image(const Image& image) {
    validate_image_size(image.rows, image.columns);
    const std::size_t expected = static_cast<std::size_t>(image.rows) * static_cast<std::size_t>(image.columns);
    if (image.pixels.size() != expected) {
        throw std::invalid_argument("image.pixels.size() is " + std::to_string(image.pixels.size()) +
                                    ", expected image.rows * image.columns = " + std::to_string(image.rows) + " * " +
                                    std::to_string(image.columns) + " = " + std::to_string(expected));
    }
}

}  // namespace phongrast
