// The chart lists a report embeds (src/catena/io/report.cpp): the plain one ("catena-charts")
// and the one with markers and animation frames ("catena-charts-extra"); empty when absent.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

inline nlohmann::json chart_list(const std::string& html, const std::string& id) {
  const std::string open = "<script type=\"application/json\" id=\"" + id + "\">";
  const std::size_t at = html.find(open);
  if (at == std::string::npos) return nlohmann::json::array();
  const std::size_t from = at + open.size();
  return nlohmann::json::parse(html.substr(from, html.find("</script>", from) - from));
}
