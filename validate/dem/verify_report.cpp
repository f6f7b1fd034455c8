// verify-dem's report.html: every case's checks as a table and its plots as
// inline SVG, pictures as embedded PNGs: one file, no network.
#include <algorithm>
#include <cmath>
#include <cstdio>


#include "src/image_io.h"
#include "validate/dem/verify_dem.h"
#include "validate/report/report_html.h"

namespace sandpic {
namespace {

// Round limits for an axis: [lo, hi] widened to a step of 1, 2 or 5 × 10^k.
std::pair<double, double> nice(double lo, double hi) {
  if (!(hi > lo)) hi = lo + 1;
  const double raw = (hi - lo) / 5, mag = std::pow(10, std::floor(std::log10(raw)));
  const double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
  return {std::floor(lo / step) * step, std::ceil(hi / step) * step};
}

const char* kColours[] = {"#1f5fb4", "#d2472a", "#2a9d4a", "#8c4fb3", "#c78a14", "#17a2b8", "#555", "#e377c2"};

std::string svg(const VerifyPlot& p) {
  const int W = 560, H = 320, L = 60, R = 150, T = 28, B = 44;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const PlotSeries& s : p.series)
    for (size_t i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
        x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]), y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
  if (x0 > x1) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  std::tie(x0, x1) = nice(x0, x1);
  std::tie(y0, y1) = nice(y0, y1);
  auto X = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
  auto Y = [&](double y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };
  std::string o = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(W) + "\" height=\"" +
                  std::to_string(H) + "\" font-family=\"sans-serif\" font-size=\"11\">\n<text x=\"" + std::to_string(L) +
                  "\" y=\"16\" font-weight=\"bold\">" + html_escape(p.title) + "</text>\n";
  for (int i = 0; i <= 5; ++i) {
    const double x = x0 + (x1 - x0) * i / 5, y = y0 + (y1 - y0) * i / 5;
    o += "<line x1=\"" + html_number("%.1f", X(x)) + "\" y1=\"" + std::to_string(T) + "\" x2=\"" + html_number("%.1f", X(x)) + "\" y2=\"" +
         std::to_string(H - B) + "\" stroke=\"#eee\"/><text x=\"" + html_number("%.1f", X(x) - 10) + "\" y=\"" +
         std::to_string(H - B + 14) + "\">" + html_number("%.4g", x) + "</text>\n";
    o += "<line x1=\"" + std::to_string(L) + "\" y1=\"" + html_number("%.1f", Y(y)) + "\" x2=\"" + std::to_string(W - R) + "\" y2=\"" +
         html_number("%.1f", Y(y)) + "\" stroke=\"#eee\"/><text x=\"4\" y=\"" + html_number("%.1f", Y(y) + 4) + "\">" + html_number("%.4g", y) +
         "</text>\n";
  }
  o += "<rect x=\"" + std::to_string(L) + "\" y=\"" + std::to_string(T) + "\" width=\"" + std::to_string(W - L - R) +
       "\" height=\"" + std::to_string(H - T - B) + "\" fill=\"none\" stroke=\"#000\"/>\n";
  o += "<text x=\"" + std::to_string(L + 80) + "\" y=\"" + std::to_string(H - 8) + "\">" + html_escape(p.x_label) +
       "</text><text x=\"4\" y=\"" + std::to_string(T - 4) + "\">" + html_escape(p.y_label) + "</text>\n";
  for (size_t k = 0; k < p.series.size(); ++k) {
    const PlotSeries& s = p.series[k];
    const char* c = kColours[k % 8];
    if (s.points) {
      for (size_t i = 0; i < s.x.size(); ++i)
        if (std::isfinite(s.y[i]))
          o += "<circle cx=\"" + html_number("%.1f", X(s.x[i])) + "\" cy=\"" + html_number("%.1f", Y(s.y[i])) + "\" r=\"3.5\" fill=\"" + c +
               "\"><title>" + html_escape(s.label) + ": " + html_number("%.4g", s.x[i]) + ", " + html_number("%.4g", s.y[i]) + "</title></circle>\n";
    } else {
      std::string pts;
      for (size_t i = 0; i < s.x.size(); ++i)
        if (std::isfinite(s.y[i])) pts += html_number("%.1f", X(s.x[i])) + "," + html_number("%.1f", Y(s.y[i])) + " ";
      o += "<polyline fill=\"none\" stroke=\"" + std::string(c) + "\" stroke-width=\"1.6\" points=\"" + pts + "\"/>\n";
    }
    const int ly = T + 14 + 16 * int(k);
    o += "<rect x=\"" + std::to_string(W - R + 10) + "\" y=\"" + std::to_string(ly - 8) + "\" width=\"10\" height=\"10\" fill=\"" +
         c + "\"/><text x=\"" + std::to_string(W - R + 24) + "\" y=\"" + std::to_string(ly + 1) + "\">" + html_escape(s.label) +
         "</text>\n";
  }
  return o + "</svg>\n";
}

}  // namespace

std::string verify_html(const VerifyReport& r) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>sandpic verify-dem</title>\n"
      "<style>body{font-family:sans-serif;margin:24px;max-width:1300px}table{border-collapse:collapse;margin:8px 0}"
      "td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}th{background:#f3f3f3}td.l{text-align:left}"
      ".pass{color:#070}.fail{color:#b00;font-weight:bold}.plots{display:flex;gap:12px;flex-wrap:wrap}"
      ".pics{display:flex;gap:12px;flex-wrap:wrap}.pics img{max-width:600px;image-rendering:pixelated;"
      "border:1px solid #999}</style></head><body>\n";
  int failed = 0;
  for (const VerifyCase& c : r.cases) failed += !c.pass();
  std::string sets;
  for (const std::string& a : r.sets) sets += " --set " + a;
  h += "<h1>sandpic verify-dem" + std::string(r.quick ? " --quick" : "") + html_escape(sets) + "</h1>\n<p class=\"" +
       (r.pass() ? "pass\">every case passes" : "fail\">" + std::to_string(failed) + " of " + std::to_string(r.cases.size()) +
                                                     " cases fail") +
       " &middot; " + html_number("%.0f", r.seconds) + " s</p>\n<table><tr><th>case</th><th>checks</th><th>result</th><th>s</th></tr>\n";
  for (const VerifyCase& c : r.cases) {
    int bad = 0;
    for (const VerifyCheck& k : c.checks) bad += !k.pass();
    h += "<tr><td class=\"l\"><a href=\"#" + c.id + "\">" + html_escape(c.title) + "</a></td><td>" + std::to_string(c.checks.size()) +
         "</td><td class=\"" + (c.pass() ? "pass\">pass" : "fail\">" + std::to_string(bad) + " fail") + "</td><td>" +
         html_number("%.0f", c.seconds) + "</td></tr>\n";
  }
  h += "</table>\n";
  for (const auto& [id, why] : r.not_run) h += "<p>" + html_escape(id) + ": " + html_escape(why) + ".</p>\n";
  for (const VerifyCase& c : r.cases) {
    h += "<h2 id=\"" + c.id + "\">" + html_escape(c.title) + " <span class=\"" + (c.pass() ? "pass\">pass" : "fail\">fail") +
         "</span></h2>\n<p>Expected: " + html_escape(c.reference) + ".</p>\n<table><tr><th>check</th><th>measured</th><th>expected"
         "</th><th>result</th></tr>\n";
    for (const VerifyCheck& k : c.checks)
      h += "<tr><td class=\"l\">" + html_escape(k.name) + "</td><td>" + html_number("%.4g", k.measured) + (k.unit.empty() ? "" : " " + html_escape(k.unit)) +
           "</td><td class=\"l\">" + html_escape(k.rule()) + "</td><td class=\"" + (k.pass() ? "pass\">pass" : "fail\">fail") +
           "</td></tr>\n";
    h += "</table>\n";
    if (!c.notes.empty()) {
      h += "<ul>";
      for (const std::string& n : c.notes) h += "<li>" + html_escape(n) + "</li>";
      h += "</ul>\n";
    }
    h += "<div class=\"plots\">";
    for (const VerifyPlot& p : c.plots) h += svg(p);
    h += "</div>\n";
    if (!c.pictures.empty()) {
      h += "<div class=\"pics\">";
      for (const auto& [caption, img] : c.pictures) {
        if (img.empty()) continue;
        const std::vector<uchar> png = encode_png(img);
        h += "<figure><img alt=\"" + html_escape(caption) + "\" src=\"data:image/png;base64," + base64(png) + "\"><figcaption>" +
             html_escape(caption) + "</figcaption></figure>";
      }
      h += "</div>\n";
    }
  }
  return h + "</body></html>\n";
}

}  // namespace sandpic
