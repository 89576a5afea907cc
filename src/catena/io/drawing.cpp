#include "catena/io/drawing.hpp"

#include <cairo-svg.h>
#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>

#include "catena/io/atomic_file.hpp"

namespace catena::io {
namespace {

constexpr double kMarginMm = 5.0;

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string to_svg(const Drawing& d) {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  for (const Polyline& p : d.polylines) {
    for (auto [x, y] : p.points) {
      xmin = std::min(xmin, x * 1e3), xmax = std::max(xmax, x * 1e3);
      ymin = std::min(ymin, y * 1e3), ymax = std::max(ymax, y * 1e3);
    }
  }
  if (!(xmax >= xmin)) xmin = ymin = 0, xmax = ymax = 1;
  // With the document unit set to mm, cairo writes width/height with that unit and a viewBox of
  // the same numbers: the surface size is given in mm and one user unit is one millimetre.
  const double width = xmax - xmin + 2 * kMarginMm;
  const double height = ymax - ymin + 2 * kMarginMm;
  std::string svg;
  cairo_surface_t* surface = cairo_svg_surface_create_for_stream(append, &svg, width, height);
  cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_MM);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  // millimetres, y up, origin at the drawing's lower-left plus margin
  cairo_scale(cr, 1.0, -1.0);
  cairo_translate(cr, kMarginMm - xmin, -(ymax + kMarginMm));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const Polyline& p : d.polylines) {
    if (p.points.empty()) continue;
    cairo_new_path(cr);
    for (auto [x, y] : p.points) cairo_line_to(cr, x * 1e3, y * 1e3);
    if (p.closed) cairo_close_path(cr);
    cairo_set_source_rgb(cr, ((p.rgb >> 16) & 0xff) / 255.0, ((p.rgb >> 8) & 0xff) / 255.0,
                         (p.rgb & 0xff) / 255.0);
    cairo_set_line_width(cr, p.width_mm);
    cairo_stroke(cr);
  }
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cairo could not draw the SVG: ") +
                             cairo_status_to_string(status));
  }
  return svg;
}

void write_svg(const std::string& path, const Drawing& d) { write_file_atomic(path, to_svg(d)); }

void write_dxf(const std::string& path, const Drawing& d) {
  namespace fs = std::filesystem;
  const fs::path temporary = fs::path(path).string() + ".tmp-dxf";
  {
    DL_Dxf dxf;
    std::unique_ptr<DL_WriterA> dw(dxf.out(temporary.c_str(), DL_Codes::AC1009));
    if (!dw) throw std::runtime_error("cannot write '" + path + "'");
    dxf.writeHeader(*dw);
    dw->dxfString(9, "$INSUNITS");
    dw->dxfInt(70, 4);  // millimetres
    dw->sectionEnd();
    dw->sectionEntities();
    for (const Polyline& p : d.polylines) {
      const DL_Attributes attributes(p.layer, 256, -1, "BYLAYER", 1.0);
      dxf.writePolyline(*dw,
                        DL_PolylineData(static_cast<int>(p.points.size()), 0, 0, p.closed ? 1 : 0),
                        attributes);
      for (auto [x, y] : p.points) dxf.writeVertex(*dw, DL_VertexData(x * 1e3, y * 1e3, 0.0, 0.0));
      dxf.writePolylineEnd(*dw);
    }
    dw->sectionEnd();
    dw->dxfEOF();
    dw->close();
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary, error);
    throw std::runtime_error("cannot write '" + path + "'");
  }
}

std::string to_dxf(const Drawing& d) {
  namespace fs = std::filesystem;
  std::random_device random;
  const fs::path path =
      fs::temp_directory_path() / ("catena_dxf_" + std::to_string(random()) + ".dxf");
  write_dxf(path.string(), d);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  in.close();
  std::error_code ignored;
  fs::remove(path, ignored);
  return text.str();
}

namespace {
class PolylineReader : public DL_CreationAdapter {
 public:
  std::vector<Polyline> lines;
  void addPolyline(const DL_PolylineData& data) override {
    lines.push_back({attributes.getLayer(), {}, (data.flags & 1) != 0});
  }
  void addVertex(const DL_VertexData& data) override {
    if (!lines.empty()) lines.back().points.push_back({data.x * 1e-3, data.y * 1e-3});
  }
};
}  // namespace

std::vector<Polyline> read_dxf_polylines(const std::string& path) {
  DL_Dxf dxf;
  PolylineReader reader;
  if (!dxf.in(path, &reader)) throw std::runtime_error("cannot read DXF '" + path + "'");
  return reader.lines;
}

}  // namespace catena::io
