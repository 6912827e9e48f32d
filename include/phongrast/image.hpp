// A float RGB image, rows x columns, row 0 at the top.
#ifndef PHONGRAST_IMAGE_HPP
#define PHONGRAST_IMAGE_HPP

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

namespace phongrast {

struct Image {
    int rows = 0;
    int columns = 0;
    std::vector<glm::vec3> pixels;  ///< row-major, rows * columns entries

    Image() = default;
    Image(int rows_, int columns_, const glm::vec3& fill = glm::vec3(0.0f))
        : rows(rows_), columns(columns_),
          pixels(static_cast<std::size_t>(rows_) * static_cast<std::size_t>(columns_), fill) {}

    glm::vec3& at(int row, int column) {
        return pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                      static_cast<std::size_t>(column)];
    }
    const glm::vec3& at(int row, int column) const {
        return pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
                      static_cast<std::size_t>(column)];
    }
};

}  // namespace phongrast

#endif  // PHONGRAST_IMAGE_HPP
