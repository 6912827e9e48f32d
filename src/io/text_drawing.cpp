#include "text_drawing.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

namespace phongrast::io::detail {
namespace {

// FreeType and fontconfig are loaded on the first label, not linked: linked,
// their libraries (and libpng, brotli, expat, bzip2 they pull in) were
// mapped at every start of the command, about 3 ms of `phongrast
// --version` on the machine measured (docs/startup.md). Only the headers
// are used at build time; the functions come from the runtime libraries of
// the same packages (libfreetype6, libfontconfig1).
void* open_library(const char* soname, const char* package) {
    void* handle = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        const char* why = dlerror();
        throw std::runtime_error(std::string("cannot load ") + soname + " (Debian package " + package +
                                 "): " + (why ? why : "unknown error"));
    }
    return handle;  // kept for the process: labels may be drawn again
}

template <typename Function>
Function* symbol(void* library, const char* name, const char* soname) {
    void* address = dlsym(library, name);
    if (address == nullptr) throw std::runtime_error(std::string(soname) + " has no " + name);
    return reinterpret_cast<Function*>(address);
}

#define PHONGRAST_TEXT_FUNCTION(name) decltype(&::name) name = symbol<decltype(::name)>(library, #name, soname)

struct FreeTypeLibrary {
    static constexpr const char* soname = "libfreetype.so.6";
    void* library = open_library(soname, "libfreetype6");
    PHONGRAST_TEXT_FUNCTION(FT_Init_FreeType);
    PHONGRAST_TEXT_FUNCTION(FT_Done_FreeType);
    PHONGRAST_TEXT_FUNCTION(FT_New_Face);
    PHONGRAST_TEXT_FUNCTION(FT_Done_Face);
    PHONGRAST_TEXT_FUNCTION(FT_Set_Pixel_Sizes);
    PHONGRAST_TEXT_FUNCTION(FT_Load_Char);
};

struct FontconfigLibrary {
    static constexpr const char* soname = "libfontconfig.so.1";
    void* library = open_library(soname, "libfontconfig1");
    PHONGRAST_TEXT_FUNCTION(FcInitLoadConfigAndFonts);
    PHONGRAST_TEXT_FUNCTION(FcConfigDestroy);
    PHONGRAST_TEXT_FUNCTION(FcPatternCreate);
    PHONGRAST_TEXT_FUNCTION(FcPatternDestroy);
    PHONGRAST_TEXT_FUNCTION(FcPatternAddString);
    PHONGRAST_TEXT_FUNCTION(FcConfigSubstitute);
    PHONGRAST_TEXT_FUNCTION(FcDefaultSubstitute);
    PHONGRAST_TEXT_FUNCTION(FcFontMatch);
    PHONGRAST_TEXT_FUNCTION(FcPatternGetString);
};

#undef PHONGRAST_TEXT_FUNCTION

// Loaded once, on first use (thread-safe); a failure throws and is retried next time.
const FreeTypeLibrary& freetype() {
    static const FreeTypeLibrary library;
    return library;
}
const FontconfigLibrary& fontconfig() {
    static const FontconfigLibrary library;
    return library;
}

struct FontconfigDeleter {
    void operator()(FcConfig* config) const { fontconfig().FcConfigDestroy(config); }
    void operator()(FcPattern* pattern) const { fontconfig().FcPatternDestroy(pattern); }
};
template <typename T>
using FontconfigPointer = std::unique_ptr<T, FontconfigDeleter>;

struct FreeTypeDeleter {
    void operator()(FT_Library library) const { freetype().FT_Done_FreeType(library); }
    void operator()(FT_Face face) const { freetype().FT_Done_Face(face); }
};

constexpr char32_t kReplacementCharacter = 0xFFFD;

// The code points of UTF-8 text; a byte that does not start or continue a
// well-formed sequence becomes U+FFFD (one per byte, like most decoders).
std::vector<char32_t> code_points(const std::string& text) {
    std::vector<char32_t> points;
    std::size_t i = 0;
    while (i < text.size()) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const int extra = lead < 0x80 ? 0 : (lead >> 5) == 0x6 ? 1 : (lead >> 4) == 0xE ? 2 : (lead >> 3) == 0x1E ? 3 : -1;
        if (extra < 0 || i + static_cast<std::size_t>(extra) >= text.size()) {
            points.push_back(kReplacementCharacter);
            ++i;
            continue;
        }
        char32_t point = extra == 0 ? lead : static_cast<char32_t>(lead & (0x3F >> extra));
        bool well_formed = true;
        for (int k = 1; k <= extra; ++k) {
            const auto next = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
            if ((next >> 6) != 0x2) {
                well_formed = false;
                break;
            }
            point = (point << 6) | (next & 0x3F);
        }
        if (!well_formed) {
            points.push_back(kReplacementCharacter);
            ++i;
            continue;
        }
        points.push_back(point);
        i += static_cast<std::size_t>(extra) + 1;
    }
    return points;
}

// Blends one rendered glyph (8-bit coverage) into the image, clipped to it.
void blend_glyph(Image& image, const FT_Bitmap& bitmap, int left, int top, const glm::vec3& colour) {
    for (int r = 0; r < static_cast<int>(bitmap.rows); ++r) {
        const int row = top + r;
        if (row < 0 || row >= image.rows) continue;
        const unsigned char* coverage = bitmap.buffer + static_cast<std::ptrdiff_t>(r) * bitmap.pitch;
        for (int c = 0; c < static_cast<int>(bitmap.width); ++c) {
            const int column = left + c;
            if (column < 0 || column >= image.columns) continue;
            const float a = static_cast<float>(coverage[c]) / 255.0f;
            glm::vec3& pixel = image.at(row, column);
            pixel = pixel * (1.0f - a) + colour * a;
        }
    }
}

}  // namespace

std::string font_file_for(const std::string& family, const std::string& debian_package) {
    const FontconfigLibrary& fc = fontconfig();
    const FontconfigPointer<FcConfig> config(fc.FcInitLoadConfigAndFonts());
    if (!config) throw std::runtime_error("cannot read fontconfig's configuration to find the font " + family);
    const FontconfigPointer<FcPattern> pattern(fc.FcPatternCreate());
    fc.FcPatternAddString(pattern.get(), FC_FAMILY, reinterpret_cast<const FcChar8*>(family.c_str()));
    fc.FcConfigSubstitute(config.get(), pattern.get(), FcMatchPattern);
    fc.FcDefaultSubstitute(pattern.get());
    FcResult result = FcResultNoMatch;
    const FontconfigPointer<FcPattern> match(fc.FcFontMatch(config.get(), pattern.get(), &result));
    FcChar8* matched_family = nullptr;
    FcChar8* file = nullptr;
    // fontconfig always offers some font; only the family asked for will do
    // (the sheet's look is part of its contract with the user).
    if (!match || fc.FcPatternGetString(match.get(), FC_FAMILY, 0, &matched_family) != FcResultMatch ||
        family != reinterpret_cast<const char*>(matched_family) ||
        fc.FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch) {
        throw std::runtime_error("the font " + family + " is not installed (Debian package " + debian_package + ")");
    }
    return reinterpret_cast<const char*>(file);
}

void draw_text(Image& image, int left, int baseline, const std::string& text, int pixel_size,
               const std::string& font_file, const glm::vec3& colour) {
    const FreeTypeLibrary& ft = freetype();
    FT_Library raw_library = nullptr;
    if (ft.FT_Init_FreeType(&raw_library) != 0) throw std::runtime_error("cannot start FreeType to draw text");
    const std::unique_ptr<FT_LibraryRec_, FreeTypeDeleter> library(raw_library);
    FT_Face raw_face = nullptr;
    if (ft.FT_New_Face(library.get(), font_file.c_str(), 0, &raw_face) != 0) {
        throw std::runtime_error("FreeType cannot read the font file " + font_file);
    }
    const std::unique_ptr<FT_FaceRec_, FreeTypeDeleter> face(raw_face);
    if (ft.FT_Set_Pixel_Sizes(face.get(), 0, static_cast<FT_UInt>(std::max(1, pixel_size))) != 0) {
        throw std::runtime_error("the font file " + font_file + " has no size " + std::to_string(pixel_size));
    }
    int pen = left;
    for (const char32_t point : code_points(text)) {
        // A glyph the font lacks is drawn as its "missing" glyph (index 0), as FreeType does.
        if (ft.FT_Load_Char(face.get(), point, FT_LOAD_RENDER) != 0) continue;
        const FT_GlyphSlot glyph = face->glyph;
        blend_glyph(image, glyph->bitmap, pen + glyph->bitmap_left, baseline - glyph->bitmap_top, colour);
        pen += static_cast<int>(glyph->advance.x >> 6);  // 26.6 fixed point
    }
}

}  // namespace phongrast::io::detail
