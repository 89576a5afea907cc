// Drawings for CAD and for people: polylines in SI metres written as SVG (cairo) or DXF (dxflib)
// in millimetres. Files are written atomically.
#pragma once

#include <string>
#include <vector>

#include "catena/core/drawing.hpp"

namespace catena::io {

using Polyline = catena::Polyline;
using Drawing = catena::Drawing;

/// SVG text of the drawing, 1:1 in millimetres (width and height in mm, 1 user unit = 1 mm),
/// y up, with a 5 mm margin.
std::string to_svg(const Drawing& drawing);
/// Writes the drawing as SVG to `path` (atomically).
void write_svg(const std::string& path, const Drawing& drawing);
/// Writes the drawing as DXF (R12, $INSUNITS = mm) to `path`: one POLYLINE per polyline, on its
/// layer, closed ones with the closed flag. Atomic.
void write_dxf(const std::string& path, const Drawing& drawing);
/// The DXF text of the drawing (as write_dxf writes it).
std::string to_dxf(const Drawing& drawing);
/// Reads the POLYLINEs (and LWPOLYLINEs) of a DXF file back, in metres (for tests and checks).
std::vector<Polyline> read_dxf_polylines(const std::string& path);

}  // namespace catena::io
