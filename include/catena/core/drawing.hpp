// A drawing as data: polylines in SI metres on named layers. Models and analyses make drawings;
// io/drawing writes them as SVG (cairo) or DXF (dxflib) in millimetres.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace catena {

struct Polyline {
  std::string layer;                              ///< DXF layer / SVG group name
  std::vector<std::pair<double, double>> points;  ///< [m] x, y
  bool closed = false;
  double width_mm = 0.25;   ///< SVG stroke width
  unsigned rgb = 0x000000;  ///< SVG stroke colour
};

struct Drawing {
  std::string title;
  std::vector<Polyline> polylines;
};

}  // namespace catena
