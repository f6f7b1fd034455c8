#include "validate/report/report_html.h"

#include "src/image_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>


namespace sandpic {

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string html_number(const char* fmt, double v) {
  if (!std::isfinite(v)) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

namespace {


std::string png_uri(const cv::Mat& img) {
  if (img.empty()) return "";
  return "data:image/png;base64," + base64(encode_png(img));
}

struct Point {
  std::string label, group;
  double t, e;
};

}  // namespace

std::string base64(const std::vector<unsigned char>& b) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string o;
  o.reserve((b.size() + 2) / 3 * 4);
  for (size_t i = 0; i < b.size(); i += 3) {
    uint32_t n = uint32_t(b[i]) << 16 | (i + 1 < b.size() ? uint32_t(b[i + 1]) << 8 : 0) |
                 (i + 2 < b.size() ? uint32_t(b[i + 2]) : 0);
    o += k[n >> 18 & 63];
    o += k[n >> 12 & 63];
    o += i + 1 < b.size() ? k[n >> 6 & 63] : '=';
    o += i + 2 < b.size() ? k[n & 63] : '=';
  }
  return o;
}

std::string error_time_svg(const Validation& v) {
  std::vector<Point> pts;
  double floor = v.metrics.empty() ? 0 : v.metrics[0].floor;
  pts.push_back({"lattice", "lattice", v.lattice_s, v.lattice.mean.silhouette_error});
  pts.push_back({"DEM (seed to seed)", "dem", v.dem_s, floor});
  for (const ValidationRun& r : v.sweep)
    if (r.skipped.empty() && r.simulate_s > 0) pts.push_back({r.setting, r.group, r.simulate_s, r.mean.silhouette_error});
  const int W = 760, H = 420, L = 70, R = 20, T = 20, B = 50;
  double t0 = 1e300, t1 = 0, e1 = 1.3 * floor;
  for (auto& p : pts)
    if (p.t > 0 && std::isfinite(p.e)) t0 = std::min(t0, p.t), t1 = std::max(t1, p.t), e1 = std::max(e1, p.e);
  if (!(t1 > 0)) t0 = 1e-3, t1 = 1;
  double lt0 = std::floor(std::log10(t0)), lt1 = std::max(lt0 + 1, std::ceil(std::log10(t1)));
  e1 = e1 > 0 ? e1 * 1.1 : 1;
  auto X = [&](double t) { return L + (std::log10(t) - lt0) / (lt1 - lt0) * (W - L - R); };
  auto Y = [&](double e) { return H - B - e / e1 * (H - T - B); };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(W) + "\" height=\"" +
                  std::to_string(H) + "\" viewBox=\"0 0 " + std::to_string(W) + " " + std::to_string(H) +
                  "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  s += "<rect x=\"" + std::to_string(L) + "\" y=\"" + std::to_string(T) + "\" width=\"" + std::to_string(W - L - R) +
       "\" height=\"" + std::to_string(H - T - B) + "\" fill=\"none\" stroke=\"#000\"/>\n";
  for (double d = lt0; d <= lt1; ++d) {
    double x = X(std::pow(10, d));
    s += "<line x1=\"" + html_number("%.1f", x) + "\" y1=\"" + std::to_string(T) + "\" x2=\"" + html_number("%.1f", x) + "\" y2=\"" +
         std::to_string(H - B) + "\" stroke=\"#ddd\"/><text x=\"" + html_number("%.1f", x - 12) + "\" y=\"" +
         std::to_string(H - B + 16) + "\">1e" + std::to_string(int(d)) + " s</text>\n";
  }
  for (int i = 0; i <= 4; ++i) {
    double e = e1 * i / 4, y = Y(e);
    s += "<line x1=\"" + std::to_string(L) + "\" y1=\"" + html_number("%.1f", y) + "\" x2=\"" + std::to_string(W - R) +
         "\" y2=\"" + html_number("%.1f", y) + "\" stroke=\"#eee\"/><text x=\"6\" y=\"" + html_number("%.1f", y + 4) + "\">" +
         html_number("%.4f", e) + "</text>\n";
  }
  for (auto [m, label] : {std::pair{1.0, "noise floor"}, std::pair{1.25, "1.25 × floor"}}) {
    double y = Y(floor * m);
    s += "<line x1=\"" + std::to_string(L) + "\" y1=\"" + html_number("%.1f", y) + "\" x2=\"" + std::to_string(W - R) +
         "\" y2=\"" + html_number("%.1f", y) + "\" stroke=\"#2a7\" stroke-dasharray=\"5,4\"/><text x=\"" +
         std::to_string(W - R - 80) + "\" y=\"" + html_number("%.1f", y - 4) + "\" fill=\"#2a7\">" + label + "</text>\n";
  }
  s += "<text x=\"" + std::to_string(W / 2 - 80) + "\" y=\"" + std::to_string(H - 10) +
       "\">simulate time (log)</text><text x=\"12\" y=\"14\">silhouette error vs the DEM runs</text>\n";
  for (auto& p : pts) {
    if (!(p.t > 0) || !std::isfinite(p.e)) continue;
    const char* colour = p.group == "lattice" ? "#d22" : p.group == "dem" ? "#222" : p.group == "sweep-lattice" ? "#e88" : "#58c";
    double x = X(p.t), y = Y(p.e);
    s += "<circle cx=\"" + html_number("%.1f", x) + "\" cy=\"" + html_number("%.1f", y) + "\" r=\"5\" fill=\"" + colour + "\"><title>" +
         html_escape(p.label) + ": " + html_number("%.4g", p.t) + " s, error " + html_number("%.4f", p.e) + "</title></circle>\n";
    s += "<text x=\"" + html_number("%.1f", x + 7) + "\" y=\"" + html_number("%.1f", y - 5) + "\" font-size=\"9\" fill=\"#555\">" +
         html_escape(p.label) + "</text>\n";
  }
  s += "</svg>\n";
  return s;
}

std::string validation_html(const Validation& v, const std::string& reproduce) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>sandpic validation</title>\n"
      "<style>body{font-family:sans-serif;margin:24px;max-width:1400px}table{border-collapse:collapse;margin:8px 0}"
      "td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}th{background:#f3f3f3}td.l{text-align:left}"
      ".pics{display:flex;gap:12px;flex-wrap:wrap}.pics figure{margin:0}.pics img{width:420px;image-rendering:pixelated;"
      "border:1px solid #999}.bad{color:#b00}.good{color:#070}</style></head><body>\n";
  h += "<h1>sandpic validation</h1>\n<p>" + html_escape(reproduce) + " &middot; " + std::to_string(v.scene.window.width) + "&times;" +
       std::to_string(v.scene.window.height) + " px &middot; " + std::to_string(v.lattice.grains) + " grains &middot; " +
       std::to_string(v.dem.size()) + " DEM runs (physics seeds " + std::to_string(v.dem.front().physics_seed) + "&ndash;" +
       std::to_string(v.dem.back().physics_seed) + ")</p>\n";
  h += "<h2>Headline</h2>\n<p>Lattice " + html_number("%.4g", v.lattice_s) + " s, DEM " + html_number("%.4g", v.dem_s) +
       " s (medians of simulate time): the lattice is <b>" + html_number("%.0f", v.time_ratio) + "&times;</b> faster.</p>\n";
  // With several lattice seeds, their own spread beside the DEM's: a lattice
  // far from the DEM but close to itself is biased, not noisy.
  const size_t seeds = 1 + v.lattice_seeds.size();
  h += "<table><tr><th>metric</th><th>lattice vs DEM</th><th>DEM vs DEM (noise floor)</th>" +
       std::string(seeds > 1 ? "<th>lattice seed to seed</th>" : "") + "<th>error ratio</th></tr>\n";
  for (const MetricRow& m : v.metrics) {
    const bool good = m.ratio <= 1.25;
    h += "<tr><td class=\"l\">" + m.name + "</td><td>" + html_number("%.5f", m.lattice) + "</td><td>" + html_number("%.5f", m.floor) +
         "</td>" + (seeds > 1 ? "<td>" + html_number("%.5f", m.spread) + "</td>" : "") + "<td class=\"" +
         (good ? "good" : "bad") + "\">" + html_number("%.3f", m.ratio) + "</td></tr>\n";
  }
  h += "</table>\n<p>error ratio: lattice-vs-DEM error over the mean DEM-vs-DEM error (1 &minus; SSIM for the SSIMs, "
       "the mean squared difference for PSNR); 1 means the preview is as close to the physics as two physical runs "
       "are to each other." +
       (seeds > 1 ? " The lattice's figures are means over its " + std::to_string(seeds) + " physics seeds (" +
                        std::to_string(v.lattice.physics_seed) + "&ndash;" +
                        std::to_string(v.lattice_seeds.back().physics_seed) + ") and every DEM run."
                  : std::string()) +
       "</p>\n";
  h += "<h2>Pictures</h2>\n<div class=\"pics\">\n";
  auto fig = [&](const cv::Mat& img, const std::string& caption) {
    h += "<figure><img class=\"pic\" alt=\"" + html_escape(caption) + "\" src=\"" + png_uri(img) + "\"><figcaption>" +
         html_escape(caption) + "</figcaption></figure>\n";
  };
  fig(v.lattice.picture, "lattice");
  fig(v.dem.front().picture, "DEM, physics seed " + std::to_string(v.dem.front().physics_seed));
  if (v.dem.size() > 1) fig(v.dem[1].picture, "DEM, physics seed " + std::to_string(v.dem[1].physics_seed));
  fig(v.heat_map, "difference (blurred luminance; outlines: lattice white, DEM cyan)");
  h += "</div>\n<h2>Error against run time</h2>\n" + error_time_svg(v);
  h += "<table><tr><th>run</th><th>simulate s</th><th>silhouette</th><th>composition</th><th>SSIM</th>"
       "<th>SSIM blurred</th><th>PSNR dB</th></tr>\n";
  auto row = [&](const ValidationRun& r, const std::string& name) {
    if (!r.skipped.empty()) {
      h += "<tr><td class=\"l\">" + html_escape(name) + "</td><td colspan=\"6\" class=\"l\">" + html_escape(r.skipped) + "</td></tr>\n";
      return;
    }
    h += "<tr><td class=\"l\">" + html_escape(name) + "</td><td>" + html_number("%.4g", r.simulate_s) + "</td><td>" +
         html_number("%.5f", r.mean.silhouette_error) + "</td><td>" + html_number("%.5f", r.mean.composition_error) + "</td><td>" +
         html_number("%.4f", r.mean.ssim) + "</td><td>" + html_number("%.4f", r.mean.ssim_blurred) + "</td><td>" + html_number("%.2f", r.mean.psnr_db) +
         "</td></tr>\n";
  };
  row(v.lattice, "lattice (as the scene says)");
  for (const ValidationRun& r : v.sweep) row(r, r.setting);
  h += "</table>\n<p>Each run against every DEM run of the ensemble, means. DEM runs:</p><table><tr><th>run</th>"
       "<th>physics seed</th><th>simulate s</th><th>kept from before</th></tr>\n";
  for (const ValidationRun& d : v.dem)
    h += "<tr><td class=\"l\">" + html_escape(d.label) + "</td><td>" + std::to_string(d.physics_seed) + "</td><td>" +
         html_number("%.4g", d.simulate_s) + "</td><td>" + (d.cached ? "yes" : "no") + "</td></tr>\n";
  h += "</table>\n";
  if (!v.notes.empty()) {
    h += "<h2>Notes</h2><ul>\n";
    for (auto& n : v.notes) h += "<li>" + html_escape(n) + "</li>\n";
    h += "</ul>\n";
  }
  // An embedded picture that fails to decode is a broken report: say so on
  // the console, where the headless-browser test looks.
  h += "<script>for (const img of document.querySelectorAll('img.pic')) {"
       " const check = () => { if (!img.naturalWidth) console.error('sandpic report: picture failed: ' + img.alt); };"
       " if (img.complete) check(); else { img.addEventListener('load', check); img.addEventListener('error', check); } }"
       "</script>\n</body></html>\n";
  return h;
}

}  // namespace sandpic
