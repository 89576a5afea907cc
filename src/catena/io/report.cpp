#include "catena/io/report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace catena::io {
namespace {

// JSON string literal, safe inside an HTML <script> element ("<" never appears raw).
std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '<':
        out += "\\u003c";
        break;
      case '>':
        out += "\\u003e";
        break;
      case '&':
        out += "\\u0026";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
          out += buffer;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string json_numbers(const std::vector<double>& values) {
  std::string out = "[";
  char buffer[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out += ",";
    if (std::isfinite(values[i])) {
      std::snprintf(buffer, sizeof buffer, "%.10g", values[i]);
      out += buffer;
    } else {
      out += "null";
    }
  }
  return out + "]";
}

// Makes the ids of one inlined SVG document unique in the page (cairo names its glyphs and
// surfaces the same way in every drawing) and drops the XML declaration.
std::string inline_svg(std::string svg, int index) {
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  svg.erase(0, svg.find_first_not_of(" \t\r\n"));
  const std::string prefix = "catena-d" + std::to_string(index) + "-";
  for (const std::string& marker :
       {std::string("id=\""), std::string("href=\"#"), std::string("url(#")}) {
    for (std::size_t at = svg.find(marker); at != std::string::npos;
         at = svg.find(marker, at + marker.size() + prefix.size())) {
      svg.insert(at + marker.size(), prefix);
    }
  }
  return svg;
}

const char* kStyle = R"css(
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:0;color:#1d2330;background:#f6f7f9}
header{background:#1d2a44;color:#fff;padding:18px 28px}
header h1{margin:0 0 6px;font-size:22px}
header .meta{font-size:13px;opacity:.85}
header code{color:#fff}
main{max-width:1100px;margin:0 auto;padding:18px 28px 60px}
nav{margin:12px 0 18px;font-size:14px}
nav a{margin-right:14px}
section{background:#fff;border:1px solid #dde1e8;border-radius:6px;padding:16px 20px;margin:18px 0}
h2{margin:0 0 4px;font-size:19px}
.source{font-size:13px;color:#555;margin-bottom:10px}
table{border-collapse:collapse;margin:8px 0 14px;font-size:14px}
th,td{border-bottom:1px solid #e4e7ec;padding:4px 10px;text-align:left;vertical-align:top}
td.value{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
td.text{max-width:640px}
.grid{overflow-x:auto;max-width:100%}
.grid td.n{color:#777}
.results{overflow-x:auto;max-width:100%}
.grid td{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
tr.best td{background:#c8e6c9;font-weight:600}
caption{text-align:left;font-weight:600;padding:6px 0}
#about p,.note p{margin:6px 0;font-size:15px;line-height:1.45}
.note{background:#f2f5fa;border-radius:4px;padding:4px 12px;margin:8px 0}
.diagnostic{border-left:4px solid;padding:6px 10px;margin:6px 0;font-size:14px}
.diagnostic.error{border-color:#c62828;background:#fdecea}
.diagnostic.warning{border-color:#e0a100;background:#fff6dd}
.diagnostic.info{border-color:#1565c0;background:#e8f1fc}
.findings{list-style:none;padding:0;margin:8px 0}
.findings li{border-left:4px solid;padding:4px 10px;margin:4px 0;font-size:14px}
.findings li.error{border-color:#c62828;background:#fdecea}
.findings li.warning{border-color:#e0a100;background:#fff6dd}
.findings li.info{border-color:#1565c0;background:#e8f1fc}
.findings .sev{font-weight:600;text-transform:uppercase;font-size:12px;margin-right:6px}
.legend{font-size:13px;color:#333;margin:4px 0 0}
.legend .swatch{display:inline-block;width:18px;height:3px;vertical-align:middle;margin:0 4px 0 12px}
.drawing .caption{font-size:14px;font-weight:600;margin:4px 0}
.note{font-size:13px;color:#333;margin:-6px 0 12px}
.diagnostic .limit{color:#444}
.failure{border-left:4px solid #c62828;background:#fdecea;padding:8px 10px;white-space:pre-wrap}
.chart{width:100%;height:380px;margin:10px 0}
.drawing{border:1px solid #e4e7ec;margin:10px 0;padding:6px;background:#fff}
.drawing svg{width:100%;height:auto;max-height:560px}
.ok{color:#2e7d32}
footer{font-size:12px;color:#666;margin-top:30px}
summary{cursor:pointer}
)css";

const char* kChartCode = R"js(
(function () {
  var charts = JSON.parse(document.getElementById('catena-charts').textContent);
  charts.forEach(function (c) {
    // several curves differ by dash and marker too: lines that coincide stay distinguishable
    var dashes = ['solid', 'dash', 'dot', 'dashdot', 'longdash', 'longdashdot'];
    var symbols = ['circle', 'square', 'diamond', 'triangle-up', 'cross', 'x'];
    var several = c.traces.length > 1;
    var same = function (a, b) {
      return a.length === b.length && a.every(function (v, k) {
        return v === b[k] || (v !== null && b[k] !== null &&
                              Math.abs(v - b[k]) <= 1e-9 * Math.max(1, Math.abs(v)));
      });
    };
    var traces = c.traces.map(function (t, i) {
      var marked = several && t.x.length <= 60;
      // a curve that lies on an earlier one says so in the legend (the warp's shares do not
      // depend on the force); open markers of growing size keep each visible
      var name = t.name;
      for (var j = 0; j < i; ++j) {
        if (same(t.x, c.traces[j].x) && same(t.y, c.traces[j].y)) {
          name += ' (on ' + c.traces[j].name + ')';
          break;
        }
      }
      return {x: t.x, y: t.y, name: name, type: 'scatter', connectgaps: false,
              mode: marked ? 'lines+markers' : 'lines',
              line: {dash: several ? dashes[i % dashes.length] : 'solid'},
              marker: {symbol: symbols[i % symbols.length] + '-open', size: 7 + 4 * (i % 4),
                       line: {width: 2}}};
    });
    var layout = {title: {text: c.title, font: {size: 15}}, margin: {l: 70, r: 20, t: 45, b: 55},
                  xaxis: {title: {text: c.x}}, yaxis: {title: {text: c.y}},
                  showlegend: several, legend: {orientation: 'h', y: -0.22}};
    if (c.equal) layout.yaxis.scaleanchor = 'x';
    if (c.integer) {
      layout.xaxis.tickformat = 'd';
      var n = Math.max.apply(null, c.traces.map(function (t) { return t.x.length; }));
      layout.xaxis.dtick = Math.max(1, Math.ceil(n / 20));
    }
    Plotly.newPlot(c.id, traces, layout, {responsive: true, displaylogo: false});
  });
})();
)js";

// Charts with markers (labelled vertical lines) or frames (an animation with a slider and a play
// button). Written into a report only when it has such a chart, so that the reports without one
// stay as they were.
const char* kExtraChartCode = R"js(
(function () {
  var charts = JSON.parse(document.getElementById('catena-charts-extra').textContent);
  charts.forEach(function (c) {
    var colours = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b'];
    var animated = c.frames && c.frames.length > 0;
    var traces = c.traces.map(function (t, i) {
      // in an animation the last curve is what moves (the chain): drawn with its nodes
      var nodes = animated && i === c.traces.length - 1;
      return {x: t.x, y: t.y, name: t.name, type: 'scatter', connectgaps: false,
              mode: nodes ? 'lines+markers' : 'lines',
              line: {color: colours[i % colours.length], width: nodes ? 2 : 1.2},
              marker: {size: 6, color: colours[i % colours.length]}};
    });
    var layout = {title: {text: c.title, font: {size: 15}}, margin: {l: 70, r: 20, t: 45, b: 55},
                  xaxis: {title: {text: c.x}}, yaxis: {title: {text: c.y}},
                  showlegend: c.traces.length > 1, legend: {orientation: 'h', y: -0.22}};
    if (c.equal) layout.yaxis.scaleanchor = 'x';
    if (c.markers && c.markers.length) {
      layout.shapes = c.markers.map(function (m) {
        return {type: 'line', xref: 'x', yref: 'paper', x0: m.x, x1: m.x, y0: 0, y1: 1,
                line: {color: '#555', width: 1, dash: 'dot'}};
      });
      layout.annotations = c.markers.map(function (m) {
        return {x: m.x, xref: 'x', y: 1, yref: 'paper', text: m.label, showarrow: false,
                textangle: -90, xanchor: 'right', yanchor: 'top', font: {size: 11, color: '#333'}};
      });
    }
    var figure = {data: traces, layout: layout};
    if (animated) {
      // fixed axes over every frame: the view does not jump while the animation plays
      var lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
      var extend = function (t) {
        [t.x, t.y].forEach(function (v, a) {
          v.forEach(function (q) {
            if (q !== null) { lo[a] = Math.min(lo[a], q); hi[a] = Math.max(hi[a], q); }
          });
        });
      };
      c.traces.forEach(extend);
      c.frames.forEach(function (f) { f.traces.forEach(extend); });
      var pad = 0.04 * Math.max(hi[0] - lo[0], hi[1] - lo[1]);
      layout.xaxis.range = [lo[0] - pad, hi[0] + pad];
      layout.yaxis.range = [lo[1] - pad, hi[1] + pad];
      layout.xaxis.autorange = false;
      layout.yaxis.autorange = false;
      layout.margin.b = 130;
      layout.legend.y = -0.45;
      var still = {mode: 'immediate', frame: {duration: 0, redraw: false}, transition: {duration: 0}};
      layout.updatemenus = [{type: 'buttons', direction: 'left', showactive: false, x: 0, y: -0.12,
                             xanchor: 'left', yanchor: 'top', pad: {t: 30, r: 10},
                             buttons: [
                               {label: 'Play', method: 'animate',
                                args: [null, {mode: 'immediate', fromcurrent: true,
                                              frame: {duration: 80, redraw: false},
                                              transition: {duration: 0}}]},
                               {label: 'Pause', method: 'animate', args: [[null], still]}]}];
      layout.sliders = [{active: 0, x: 0.16, len: 0.84, y: -0.12, xanchor: 'left', yanchor: 'top',
                         pad: {t: 30}, font: {size: 9}, ticklen: 3,
                         currentvalue: {font: {size: 12}},
                         steps: c.frames.map(function (f, k) {
                           return {label: f.name, method: 'animate', args: [['f' + k], still]};
                         })}];
      var first = c.traces.length - c.frames[0].traces.length;
      figure.frames = c.frames.map(function (f, k) {
        return {name: 'f' + k,
                data: f.traces.map(function (t) { return {x: t.x, y: t.y}; }),
                traces: f.traces.map(function (t, k) { return first + k; })};
      });
    }
    Plotly.newPlot(c.id, figure.data, figure.layout, {responsive: true, displaylogo: false})
        .then(function (gd) { if (figure.frames) return Plotly.addFrames(gd, figure.frames); });
  });
})();
)js";

}  // namespace

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      case '\t':
      case '\n':
      case '\r':
        out += c;
        break;
      default: {
        // C0 controls and DEL are not allowed in HTML text (NUL least of all): shown as their
        // Unicode control pictures, U+2400 + c (␀, ␁, …) and U+2421 (␡), so nothing is lost.
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
          const unsigned code = u == 0x7f ? 0x2421u : 0x2400u + u;
          out += static_cast<char>(0xe0 | (code >> 12));
          out += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
          out += static_cast<char>(0x80 | (code & 0x3f));
        } else {
          out += c;
        }
      }
    }
  }
  return out;
}

namespace {

// Prose of the case (its description, a table's note) as HTML paragraphs: a blank line starts a
// new one, other line breaks are spaces; the text is escaped, never markup.
std::string paragraphs(std::string_view text) {
  std::string out, paragraph;
  auto flush = [&] {
    const auto first = paragraph.find_first_not_of(' ');
    if (first != std::string::npos)
      out += "<p>" +
             html_escape(paragraph.substr(first, paragraph.find_last_not_of(' ') - first + 1)) +
             "</p>";
    paragraph.clear();
  };
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find_first_not_of(" \t") == std::string_view::npos) {
      flush();
    } else {
      if (!paragraph.empty()) paragraph += ' ';
      paragraph += line;
    }
    start = end + 1;
  }
  flush();
  return out;
}

}  // namespace

std::string to_html(const Report& report, std::string_view chart_script) {
  std::ostringstream html;
  auto table = [&](const std::string& caption, const std::vector<ReportRow>& rows,
                   const char* name_header) {
    html << "<table>";
    if (!caption.empty()) html << "<caption>" << html_escape(caption) << "</caption>";
    html << "<tr><th>" << name_header << "</th><th>value</th><th>unit</th></tr>";
    for (const ReportRow& r : rows) {
      // numbers line up on the right; words and sentences wrap on the left
      const bool numeric =
          !r.value.empty() && r.value.find_first_not_of("0123456789.eE+-, ") == std::string::npos;
      html << "<tr><td>" << html_escape(r.name) << "</td><td class=\""
           << (numeric ? "value" : "text") << "\">" << html_escape(r.value) << "</td><td>"
           << html_escape(r.unit) << "</td></tr>";
    }
    html << "</table>\n";
  };
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
       << "<meta name=\"generator\" content=\"Catena " << html_escape(report.version) << "\">"
       << "<title>" << html_escape(report.title) << " — Catena report</title><style>" << kStyle
       << "</style></head><body>\n";
  html << "<header><h1>" << html_escape(report.title) << "</h1><div class=\"meta\">Catena "
       << html_escape(report.version) << " · case <code>" << html_escape(report.case_name)
       << "</code> · SHA-256 <code id=\"case-hash\">" << html_escape(report.case_hash)
       << "</code></div></header>\n<main>\n<nav>";
  html << "<a href=\"#inputs\">Inputs</a>";
  for (const ReportSection& s : report.sections)
    html << "<a href=\"#" << html_escape(s.id) << "\">" << html_escape(s.title) << "</a>";
  html << "</nav>\n";

  // the findings first, each with its analysis and a link to it: what an engineer looks for
  // before the numbers. A failure to run is an error; info notes are not warnings.
  int errors = 0, warnings = 0, notes = 0;
  std::ostringstream list;
  for (const ReportSection& s : report.sections) {
    auto item = [&](const std::string& severity, const std::string& anchor,
                    const std::string& text) {
      const char* shown = severity == "error" ? "error" : severity == "info" ? "note" : "warning";
      (severity == "error" ? errors : severity == "info" ? notes : warnings)++;
      list << "<li class=\"" << (severity == "error" || severity == "info" ? severity : "warning")
           << "\"><span class=\"sev\">" << shown << "</span><a href=\"#" << html_escape(anchor)
           << "\">" << html_escape(s.title) << "</a>: " << html_escape(text) << "</li>\n";
    };
    if (!s.failure.empty()) item("error", s.id, "could not run: " + s.failure);
    for (std::size_t i = 0; i < s.diagnostics.size(); ++i)
      item(s.diagnostics[i].severity, s.id + "-finding-" + std::to_string(i + 1),
           s.diagnostics[i].message);
  }
  auto count = [](int n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  if (!report.description.empty())
    html << "<section id=\"about\">" << paragraphs(report.description) << "</section>\n";
  html << "<section id=\"summary\"><h2>Findings</h2>";
  if (errors + warnings + notes == 0) {
    html << "<p class=\"ok\">Every check of every analysis passed.</p>";
  } else {
    html << "<p>" << count(errors, "error", "errors") << ", "
         << count(warnings, "warning", "warnings") << ", " << count(notes, "note", "notes")
         << (errors + warnings == 0 ? ": every check passed." : ".")
         << "</p><ul class=\"findings\">" << list.str() << "</ul>";
  }
  html << "</section>\n";

  html << "<section id=\"inputs\"><details><summary><h2 style=\"display:inline\">Inputs</h2> ("
       << report.inputs.size()
       << " values)</summary><div class=\"source\">The case file's values as typed; a bare "
          "number is in the field's default unit, named beside it (docs/units.md).</div>";
  table("", report.inputs, "path");
  html << "</details></section>\n";

  std::string charts_json = "[", extra_json = "[";
  int chart_count = 0, drawing_count = 0, plain_count = 0, extra_count = 0;
  for (const ReportSection& s : report.sections) {
    html << "<section id=\"" << html_escape(s.id) << "\" class=\"analysis\"><h2>"
         << html_escape(s.title) << "</h2><div class=\"source\">Source: " << html_escape(s.source);
    if (!s.docs.empty())
      html << " · model documentation: <code>" << html_escape(s.docs) << "</code>";
    html << "</div>\n";
    if (!s.note.empty()) html << "<div class=\"note\">" << paragraphs(s.note) << "</div>\n";
    if (!s.failure.empty()) {
      html << "<div class=\"failure\">This analysis could not run: " << html_escape(s.failure)
           << "</div></section>\n";
      continue;
    }
    for (std::size_t i = 0; i < s.diagnostics.size(); ++i) {
      const ReportDiagnostic& d = s.diagnostics[i];
      html << "<div class=\"diagnostic " << html_escape(d.severity) << "\" id=\""
           << html_escape(s.id) << "-finding-" << i + 1 << "\"><b>"
           << (d.severity == "info" ? std::string("note") : html_escape(d.severity)) << ":</b> "
           << html_escape(d.message);
      if (!d.limit.empty())
        html << " <span class=\"limit\">(" << html_escape(d.limit) << ")</span>";
      html << "</div>\n";
    }
    for (const ReportTable& t : s.tables) {
      html << "<div class=\"results\">";
      table(t.title, t.rows, "quantity");
      html << "</div>";
    }
    for (const ReportGrid& g : s.grids) {
      html << "<div class=\"grid\"><table><caption>" << html_escape(g.title) << "</caption><tr>";
      if (g.numbered) html << "<th>#</th>";
      for (const std::string& c : g.columns) html << "<th>" << html_escape(c) << "</th>";
      html << "</tr>";
      for (std::size_t i = 0; i < g.rows.size(); ++i) {
        html << (i < g.highlighted.size() && g.highlighted[i] ? "<tr class=\"best\">" : "<tr>");
        if (g.numbered) html << "<td class=\"n\">" << i + 1 << "</td>";
        for (const std::string& cell : g.rows[i]) html << "<td>" << html_escape(cell) << "</td>";
        html << "</tr>";
      }
      html << "</table></div>\n";
      if (!g.note.empty()) html << "<p class=\"note\">" << html_escape(g.note) << "</p>\n";
    }
    for (const ReportChart& c : s.charts) {
      const std::string id = "catena-chart-" + std::to_string(chart_count++);
      // a chart with markers or frames goes to the second list, drawn by kExtraChartCode
      const bool extra = !c.markers.empty() || !c.frames.empty();
      html << "<div class=\"chart\" id=\"" << id << "\""
           << (c.frames.empty() ? "" : " style=\"height:600px\"") << "></div>\n";
      std::string& json = extra ? extra_json : charts_json;
      if ((extra ? extra_count : plain_count)++) json += ",";
      auto traces = [&](const std::vector<ReportTrace>& curves) {
        std::string out = "[";
        for (std::size_t i = 0; i < curves.size(); ++i) {
          if (i) out += ",";
          out += "{\"name\":" + json_string(curves[i].name) +
                 ",\"x\":" + json_numbers(curves[i].x) + ",\"y\":" + json_numbers(curves[i].y) +
                 "}";
        }
        return out + "]";
      };
      json += "{\"id\":" + json_string(id) + ",\"title\":" + json_string(c.title) +
              ",\"x\":" + json_string(c.x_label) + ",\"y\":" + json_string(c.y_label) +
              ",\"equal\":" + (c.equal_axes ? "true" : "false") +
              ",\"integer\":" + (c.integer_x ? "true" : "false") +
              ",\"traces\":" + traces(c.traces);
      if (!c.markers.empty()) {
        json += ",\"markers\":[";
        for (std::size_t i = 0; i < c.markers.size(); ++i) {
          const std::string x = json_numbers({c.markers[i].x});  // "[x]"
          json += std::string(i ? "," : "") + "{\"x\":" + x.substr(1, x.size() - 2) +
                  ",\"label\":" + json_string(c.markers[i].label) + "}";
        }
        json += "]";
      }
      if (!c.frames.empty()) {
        json += ",\"frames\":[";
        for (std::size_t i = 0; i < c.frames.size(); ++i)
          json += std::string(i ? "," : "") + "{\"name\":" + json_string(c.frames[i].name) +
                  ",\"traces\":" + traces(c.frames[i].traces) + "}";
        json += "]";
      }
      json += "}";
    }
    for (std::size_t i = 0; i < s.drawings_svg.size(); ++i) {
      html << "<div class=\"drawing\">" << inline_svg(s.drawings_svg[i], drawing_count++);
      if (i < s.drawing_keys.size()) {
        const ReportDrawingKey& k = s.drawing_keys[i];
        html << "<div class=\"caption\">" << html_escape(k.caption)
             << "</div><div class=\"legend\">";
        for (const auto& [name, rgb] : k.legend) {
          char colour[8];
          std::snprintf(colour, sizeof colour, "#%06x", rgb & 0xffffffu);
          html << "<span class=\"swatch\" style=\"background:" << colour << "\"></span>"
               << html_escape(name);
        }
        if (k.scale_bar_mm > 0)
          html << "<span class=\"swatch\" style=\"background:#000;height:5px\"></span>scale bar "
               << k.scale_bar_mm << " mm";
        html << "</div>";
      }
      html << "</div>\n";
    }
    html << "</section>\n";
  }
  charts_json += "]";
  html << "<footer>Generated by Catena " << html_escape(report.version)
       << ". Every number is in the units named beside it. Charts: Plotly (MIT licence), embedded."
       << "</footer>\n</main>\n";
  html << "<script type=\"application/json\" id=\"catena-charts\">" << charts_json
       << "</script>\n<script>" << chart_script << "</script>\n<script>" << kChartCode
       << "</script>\n";
  if (extra_count)
    html << "<script type=\"application/json\" id=\"catena-charts-extra\">" << extra_json
         << "]</script>\n<script>" << kExtraChartCode << "</script>\n";
  html << "</body></html>\n";
  return html.str();
}

}  // namespace catena::io
