#include "geometry/curves/glyph_curves.h"

#include <memory>
#include <stdexcept>
#include <string>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "geometry/curves/curve_name.h"
#include "geometry/io/parse_error.h"
#include "geometry/curves/path_builder.h"

namespace curvebench::geometry {
namespace {

// A FreeType library with one open face, closed in reverse order.
class Font {
 public:
  explicit Font(const std::filesystem::path& file) {
    FT_Library library;
    if (FT_Init_FreeType(&library) != 0) throw std::runtime_error("FreeType: cannot initialise");
    library_.reset(library);
    FT_Face face;
    if (FT_New_Face(library, file.c_str(), 0, &face) != 0) throw ParseError(file.string(), 0, "FreeType cannot open this font");
    face_.reset(face);
  }

  FT_Face face() const { return face_.get(); }

  // The components of the glyph's outline, in units of the em.
  std::vector<Curve_component> outline(FT_UInt glyph) const {
    Outline_reader reader{{}, 1.0 / face_->units_per_EM, false};
    if (FT_Load_Glyph(face_.get(), glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_BITMAP) != 0 ||
        face_->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
      return {};
    static constexpr FT_Outline_Funcs callbacks{&Outline_reader::move_to, &Outline_reader::line_to,
                                                &Outline_reader::conic_to, &Outline_reader::cubic_to, 0, 0};
    if (FT_Outline_Decompose(&face_->glyph->outline, &callbacks, &reader) != 0)
      throw std::runtime_error("FreeType: cannot decompose the outline of glyph " + std::to_string(glyph));
    if (reader.in_contour) reader.builder.close();
    return reader.builder.finish();
  }

 private:
  // FT_Outline_Decompose's callbacks: every contour is closed (FreeType draws its last segment).
  struct Outline_reader {
    Path_builder builder;
    double scale;
    bool in_contour;

    Point point(const FT_Vector* v) const { return {double(v->x) * scale, double(v->y) * scale}; }
    static Outline_reader& of(void* user) { return *static_cast<Outline_reader*>(user); }
    static int move_to(const FT_Vector* to, void* user) {
      auto& r = of(user);
      if (r.in_contour) r.builder.close();
      r.builder.move_to(r.point(to));
      r.in_contour = true;
      return 0;
    }
    static int line_to(const FT_Vector* to, void* user) {
      auto& r = of(user);
      r.builder.line_to(r.point(to));
      return 0;
    }
    static int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
      auto& r = of(user);
      r.builder.quadratic_to(r.point(control), r.point(to));
      return 0;
    }
    static int cubic_to(const FT_Vector* control1, const FT_Vector* control2, const FT_Vector* to, void* user) {
      auto& r = of(user);
      r.builder.cubic_to(r.point(control1), r.point(control2), r.point(to));
      return 0;
    }
  };

  struct Close_library {
    void operator()(FT_Library library) const { FT_Done_FreeType(library); }
  };
  struct Close_face {
    void operator()(FT_Face face) const { FT_Done_Face(face); }
  };
  // Declared in this order so that the face is closed before the library.
  std::unique_ptr<FT_LibraryRec_, Close_library> library_;
  std::unique_ptr<FT_FaceRec_, Close_face> face_;
};

}  // namespace

Curve glyph_curve(const std::filesystem::path& font, char32_t code_point) {
  const Font reader(font);
  const FT_UInt glyph = FT_Get_Char_Index(reader.face(), code_point);
  const std::string name = "glyph:" + font.string() + ":" + format_code_point(code_point);
  if (glyph == 0) throw std::invalid_argument(name + ": the font has no glyph for this character");
  return Curve{name, reader.outline(glyph)};
}

std::vector<char32_t> glyph_code_points(const std::filesystem::path& font) {
  const Font reader(font);
  std::vector<char32_t> found;
  FT_UInt glyph = 0;
  for (FT_ULong code = FT_Get_First_Char(reader.face(), &glyph); glyph != 0;
       code = FT_Get_Next_Char(reader.face(), code, &glyph))
    if (!reader.outline(glyph).empty()) found.push_back(char32_t(code));
  return found;
}

}  // namespace curvebench::geometry
