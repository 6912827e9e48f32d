// Label text for the sheet (internal header): FreeType draws each glyph,
// fontconfig finds the font file by its family name.
//
// These two small libraries replace OpenImageIO's render_text. Loading
// OpenImageIO for a few labels cost the sheet about 175 ms, and the libraries
// it pulls in (DCMTK's log4cplus, OpenImageIO's own pool) start threads that
// are still being torn down while the process exits, which made
// LeakSanitizer's exit-time check crash in the sanitizer build.
#ifndef PHONGRAST_SRC_IO_TEXT_DRAWING_HPP
#define PHONGRAST_SRC_IO_TEXT_DRAWING_HPP

#include <string>

#include <glm/vec3.hpp>

#include "phongrast/image.hpp"

namespace phongrast::io::detail {

/// The font file fontconfig matches to `family` (e.g. "DejaVu Sans").
/// Throws std::runtime_error naming the family, and the Debian package
/// that provides it, when no installed font has that family (fontconfig
/// would otherwise substitute any font it has).
std::string font_file_for(const std::string& family, const std::string& debian_package);

/// Draws UTF-8 `text` into `image` with the font in `font_file` at
/// `pixel_size` pixels per em: pen starts at column `left`, glyphs sit on the
/// baseline at row `baseline`. Each glyph's coverage a (0..1) blends
/// pixel = pixel * (1 - a) + colour * a; glyph parts outside the image are
/// clipped. Invalid UTF-8 bytes are drawn as U+FFFD. Throws
/// std::runtime_error naming the font file if FreeType cannot use it.
void draw_text(Image& image, int left, int baseline, const std::string& text, int pixel_size,
               const std::string& font_file, const glm::vec3& colour);

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_TEXT_DRAWING_HPP
