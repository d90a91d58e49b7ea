// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_html.hpp"

#include <fmt/format.h>

#include "lookahead/exploration/study_report.hpp"
#include "lookahead/exploration/study_tables.hpp"

namespace lookahead::exploration {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:2em;max-width:1400px}"
    "table{border-collapse:collapse;margin:0.5em 0 1.5em}"
    "th,td{border:1px solid #bbb;padding:3px 8px;text-align:right}"
    "th{background:#eee}td:first-child,th:first-child{text-align:left}"
    ".thumbs{display:flex;flex-wrap:wrap;gap:8px}"
    "figure{margin:0;width:170px;font-size:12px}"
    "figure img{width:160px;border:1px solid #999;image-rendering:pixelated}";

std::string table_html(const StudyTable& t, const std::string& css_class) {
  std::string h = "<table class=\"" + css_class + "\">\n<tr>";
  for (const std::string& c : t.header) h += "<th>" + html_escape(c) + "</th>";
  h += "</tr>\n";
  for (const auto& row : t.rows) {
    h += "<tr>";
    for (const std::string& c : row) h += "<td>" + html_escape(c) + "</td>";
    h += "</tr>\n";
  }
  return h + "</table>\n";
}

std::string thumbnails_html(const StudySpec& spec, const StudyResult& result, std::size_t w) {
  std::string h = "<div class=\"thumbs\">\n";
  for (const std::string& strategy : spec.strategies) {
    for (const StudyRunResult* r : runs_of(spec, result, w, strategy)) {
      const std::string folder = run_id(spec, {w, strategy, r->summary.seed});
      const std::string map = "runs/" + folder + "/map.png";
      h += fmt::format(
          "<figure><a href=\"{0}\"><img class=\"run-map\" src=\"{0}\" alt=\"map of {1}\" "
          "loading=\"lazy\"></a><figcaption>{2} seed {3}<br>{4}, coverage {5:.3f}</figcaption>"
          "</figure>\n",
          html_escape(map), html_escape(folder), html_escape(strategy), r->summary.seed, html_escape(r->summary.status),
          r->summary.coverage);
    }
  }
  return h + "</div>\n";
}

std::string world_html(const StudySpec& spec, const StudyResult& result, std::size_t w) {
  const std::string label = html_escape(spec.worlds[w].label);
  std::string h =
      "<h2 id=\"world-" + label + "\">" + label + "</h2>\n" + table_html(strategy_table(spec, result, w), "strategies");
  if (spec.strategies.size() > 1) {
    h += "<h3>Welch's t-test (runs that reached 95 %)</h3>\n" + table_html(welch_table(spec, result, w), "welch") +
         "<h3>Paired on the seed (time to 95 %)</h3>\n" + table_html(paired_table(spec, result, w), "paired");
  }
  h += fmt::format("<p><img class=\"plot\" src=\"coverage_{0}.png\" alt=\"coverage of {0}\"></p>\n", label);
  return h + "<h3>Maps of the runs</h3>\n" + thumbnails_html(spec, result, w);
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
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
      default:
        out += c;
    }
  }
  return out;
}

std::string study_report_html(const StudySpec& spec, const StudyResult& result) {
  const std::string name = html_escape(spec.name);
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\">\n<head><meta charset=\"utf-8\">\n<title>Study " + name +
                  "</title>\n<style>" + kStyle + "</style></head>\n<body>\n<h1>Study " + name + "</h1>\n";
  h += fmt::format("<p id=\"overall\"><strong>{}</strong></p>\n", html_escape(overall_line(spec, result)));
  h += table_html(status_table(spec, result), "status");
  if (const auto missing = missing_runs(spec, result); !missing.empty()) {
    h += "<p>Not finished:</p>\n<ul class=\"missing\">\n";
    for (const std::string& m : missing) h += "<li>" + html_escape(m) + "</li>\n";
    h += "</ul>\n";
  }
  h += "<p>Times are simulated seconds. Files: <a href=\"results.csv\">results.csv</a>, "
       "<a href=\"summary.md\">summary.md</a>, <a href=\"plan.csv\">plan.csv</a>.</p>\n";
  for (std::size_t w = 0; w < spec.worlds.size(); ++w) h += world_html(spec, result, w);
  h += "<h2>Time to 95 % coverage</h2>\n<p><img class=\"plot\" src=\"time_to_95.png\" "
       "alt=\"time to 95 %\"></p>\n</body>\n</html>\n";
  return h;
}

}  // namespace lookahead::exploration
