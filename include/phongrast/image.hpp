// A float RGB image, rows x columns, row 0 at the top, and the one image-size
// limit the library, the phongrast command and the Python module share.
#ifndef PHONGRAST_IMAGE_HPP
#define PHONGRAST_IMAGE_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace phongrast {

/// The largest image side, in pixels (rows and columns alike). With up to
/// 16 x 16 samples per pixel that is 2^19 samples, the fixed-point coverage
/// test's budget.
inline constexpr int kMaxImageSide = 32768;
/// The most pixels an image may have (rows x columns), and the most samples a
/// render may take (rows x columns x samples_per_axis^2): 2^28, which is
/// 3 GiB of float RGB (12 bytes each). Past it memory, not the renderer, is
/// what gives out, so the size is refused up front with a message saying how
/// much memory it would take instead of ending in std::bad_alloc.
inline constexpr std::int64_t kMaxImagePixels = std::int64_t(1) << 28;
/// Bytes per pixel (or sample) of an Image: three floats.
inline constexpr std::int64_t kImageBytesPerPixel = 3 * sizeof(float);

/// Throws std::invalid_argument when `rows` or `columns` is below 1, and
/// std::length_error when either is above kMaxImageSide or their product is
/// above kMaxImagePixels. The message names the members (`rows_name`,
/// `columns_name`), the size asked for and the memory it would take.
void validate_image_size(std::int64_t rows, std::int64_t columns, const char* rows_name = "image.rows",
                         const char* columns_name = "image.columns");

struct Image;
/// Throws std::invalid_argument when image.pixels.size() is not
/// image.rows * image.columns (naming both), and what validate_image_size()
/// throws for its size: for functions that read a caller's whole image.
void validate_image(const Image& image);

namespace detail {
[[noreturn]] void throw_pixel_out_of_range(int row, int column, int rows, int columns, std::size_t pixels);
void check_image_allocation(int rows, int columns);
}  // namespace detail

struct Image {
    int rows = 0;
    int columns = 0;
    std::vector<glm::vec3> pixels;  ///< row-major, rows * columns entries

    Image() = default;
    /// Throws std::invalid_argument for a negative size and std::length_error
    /// past the limit (validate_image_size); 0 rows or columns is an empty image.
    Image(int rows_, int columns_, const glm::vec3& fill = glm::vec3(0.0f))
        : rows(rows_), columns(columns_),
          pixels((detail::check_image_allocation(rows_, columns_),
                  static_cast<std::size_t>(rows_) * static_cast<std::size_t>(columns_)),
                 fill) {}

    /// The pixel at (row, column). Throws std::out_of_range when row is not in
    /// [0, rows), column not in [0, columns), or `pixels` holds fewer than
    /// rows * columns entries (a caller resized it).
    glm::vec3& at(int row, int column) { return pixels[checked_index(row, column)]; }
    const glm::vec3& at(int row, int column) const { return pixels[checked_index(row, column)]; }

private:
    std::size_t checked_index(int row, int column) const {
        const std::size_t index =
            static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(column);
        if (row < 0 || row >= rows || column < 0 || column >= columns || index >= pixels.size()) {
            detail::throw_pixel_out_of_range(row, column, rows, columns, pixels.size());
        }
        return index;
    }
};

}  // namespace phongrast

#endif  // PHONGRAST_IMAGE_HPP
