// A labelled grid of images (the seed's eight figures on one sheet), with the
// labels drawn by FreeType in the DejaVu Sans font (fonts-dejavu-core, found
// through fontconfig).
#ifndef PHONGRAST_IO_SHEET_HPP
#define PHONGRAST_IO_SHEET_HPP

#include <string>
#include <vector>

#include "phongrast/image.hpp"

namespace phongrast::io {

struct SheetCell {
    Image image;
    std::string label;
};

/// Lays the cells out `columns` per row, each with its label in a strip above
/// it, on a white background. All cell images must have the same size.
/// Throws std::invalid_argument for an empty list or mismatched sizes.
Image compose_sheet(const std::vector<SheetCell>& cells, int columns);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_SHEET_HPP
