// SVG writer primitives: escaping, finite number formatting, nice ticks, print-safe colours.
#include "wattswath/report/svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace wattswath::report {

std::string escapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        // Control characters other than tab/newline are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          out += ' ';
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string svgNum(double value) {
  if (!std::isfinite(value)) throw std::logic_error("svg: non-finite coordinate");
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", value);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string formatNumber(double value, int decimals) {
  if (!std::isfinite(value)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", std::clamp(decimals, 0, 12), value);
  std::string s = buf;
  // "-0.0" reads as a sign error in a table: print it as zero.
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);
  return s;
}

std::string formatSignificant(double value, int digits) {
  if (!std::isfinite(value)) return "-";
  if (value == 0.0) return "0";
  const int mag = static_cast<int>(std::floor(std::log10(std::abs(value))));
  return formatNumber(value, std::max(0, std::clamp(digits, 1, 15) - 1 - mag));
}

std::string formatMinSec(double seconds) {
  if (!std::isfinite(seconds)) return "-";
  const long long whole = std::llround(std::abs(seconds));
  char buf[48];
  std::snprintf(buf, sizeof buf, "%s%lld:%02lld", seconds < 0 && whole > 0 ? "-" : "", whole / 60, whole % 60);
  return buf;
}

Ticks niceTicks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) throw std::invalid_argument("niceTicks: non-finite axis range");
  target = std::clamp(target, 2, 20);
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * mag;
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  }
  Ticks t;
  t.lo = std::floor(lo / step + 1e-9) * step;
  t.hi = std::ceil(hi / step - 1e-9) * step;
  int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  if (std::abs(step / std::pow(10.0, -decimals) - 2.5) < 1e-9) ++decimals;  // 0.25 needs 2 decimals
  const int n = static_cast<int>(std::lround((t.hi - t.lo) / step));
  for (int i = 0; i <= n; ++i) {
    const double v = t.lo + i * step;
    t.values.push_back(v);
    t.labels.push_back(formatNumber(std::abs(v) < 1e-12 * step ? 0.0 : v, decimals));
  }
  return t;
}

Ticks logTicks(double lo, double hi) {
  if (!(lo > 0.0) || !(hi > 0.0) || !std::isfinite(lo) || !std::isfinite(hi)) {
    throw std::invalid_argument("logTicks: log axis needs finite positive bounds");
  }
  if (lo > hi) std::swap(lo, hi);
  Ticks t;
  t.lo = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
  t.hi = std::pow(10.0, std::ceil(std::log10(hi) - 1e-9));
  if (t.hi <= t.lo) t.hi = t.lo * 10.0;
  const int decades = static_cast<int>(std::lround(std::log10(t.hi / t.lo)));
  const std::vector<double> mults = decades > 3 ? std::vector<double>{1.0} : std::vector<double>{1.0, 2.0, 5.0};
  for (int d = 0; d <= decades; ++d) {
    const double base = t.lo * std::pow(10.0, d);
    for (const double m : mults) {
      const double v = base * m;
      if (v > t.hi * (1 + 1e-9)) break;
      const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(v) + 1e-9)));
      t.values.push_back(v);
      t.labels.push_back(formatNumber(v, decimals));
    }
  }
  return t;
}

std::string seriesColour(std::size_t i) {
  // Okabe & Ito (2008), without black: blue, vermillion, bluish green, orange, reddish purple,
  // sky blue, yellow (last: weakest on white).
  static const std::array<const char*, 7> kPalette = {"#0072B2", "#D55E00", "#009E73", "#E69F00",
                                                      "#CC79A7", "#56B4E9", "#F0E442"};
  return kPalette[i % kPalette.size()];
}

std::string seriesDash(std::size_t i) {
  static const std::array<const char*, 5> kDashes = {"", "6 3", "2 2", "8 3 2 3", "4 4"};
  return kDashes[i % kDashes.size()];
}

std::string valueColour(double t) {
  // Viridis anchors (matplotlib), t = 0, 0.125, ..., 1; we map [0, 1] to [0, 0.875].
  static const std::array<std::array<double, 3>, 9> kViridis = {{{68, 1, 84},
                                                                 {71, 44, 122},
                                                                 {59, 81, 139},
                                                                 {44, 113, 142},
                                                                 {33, 144, 141},
                                                                 {39, 173, 129},
                                                                 {92, 200, 99},
                                                                 {170, 220, 50},
                                                                 {253, 231, 37}}};
  if (!std::isfinite(t)) t = 0.0;
  const double s = std::clamp(t, 0.0, 1.0) * 0.875 * 8.0;
  const int i = std::min(7, static_cast<int>(s));
  const double f = s - i;
  char buf[8];
  int c[3];
  for (int k = 0; k < 3; ++k) {
    c[k] = static_cast<int>(std::lround(kViridis[i][k] + f * (kViridis[i + 1][k] - kViridis[i][k])));
  }
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c[0], c[1], c[2]);
  return buf;
}

SvgWriter::SvgWriter(double width, double height) {
  out_ = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + svgNum(width) + "\" height=\"" +
         svgNum(height) + "\" viewBox=\"0 0 " + svgNum(width) + " " + svgNum(height) +
         "\" font-family=\"system-ui, -apple-system, 'Segoe UI', Roboto, 'DejaVu Sans', Helvetica, Arial, "
         "sans-serif\" font-size=\"12\">\n";
  open_.push_back("svg");
}

namespace {
std::string attrString(const Attrs& attrs) {
  std::string s;
  for (const auto& [k, v] : attrs) s += " " + k + "=\"" + escapeXml(v) + "\"";
  return s;
}
}  // namespace

SvgWriter& SvgWriter::open(const std::string& tag, const Attrs& attrs) {
  out_ += "<" + tag + attrString(attrs) + ">";
  open_.push_back(tag);
  return *this;
}

SvgWriter& SvgWriter::close() {
  if (open_.size() <= 1) throw std::logic_error("SvgWriter::close: no open element");
  out_ += "</" + open_.back() + ">\n";
  open_.pop_back();
  return *this;
}

SvgWriter& SvgWriter::leaf(const std::string& tag, const Attrs& attrs) {
  out_ += "<" + tag + attrString(attrs) + "/>\n";
  return *this;
}

SvgWriter& SvgWriter::textElement(const std::string& tag, const Attrs& attrs, const std::string& text) {
  out_ += "<" + tag + attrString(attrs) + ">" + escapeXml(text) + "</" + tag + ">\n";
  return *this;
}

SvgWriter& SvgWriter::text(double x, double y, const std::string& text, const Attrs& attrs) {
  Attrs a = {{"x", svgNum(x)}, {"y", svgNum(y)}};
  a.insert(a.end(), attrs.begin(), attrs.end());
  return textElement("text", a, text);
}

SvgWriter& SvgWriter::title(const std::string& text) { return textElement("title", {}, text); }

SvgWriter& SvgWriter::line(double x0, double y0, double x1, double y1, const Attrs& attrs) {
  Attrs a = {{"x1", svgNum(x0)}, {"y1", svgNum(y0)}, {"x2", svgNum(x1)}, {"y2", svgNum(y1)}};
  a.insert(a.end(), attrs.begin(), attrs.end());
  return leaf("line", a);
}

SvgWriter& SvgWriter::rect(double x, double y, double w, double h, const Attrs& attrs) {
  Attrs a = {{"x", svgNum(x)}, {"y", svgNum(y)}, {"width", svgNum(std::max(0.0, w))}, {"height", svgNum(std::max(0.0, h))}};
  a.insert(a.end(), attrs.begin(), attrs.end());
  return leaf("rect", a);
}

std::string SvgWriter::str() const {
  if (open_.size() != 1) throw std::logic_error("SvgWriter::str: element <" + open_.back() + "> not closed");
  return out_ + "</svg>\n";
}

std::string svgPoints(const std::vector<std::pair<double, double>>& pts) {
  std::string s;
  for (const auto& [x, y] : pts) {
    if (!s.empty()) s += ' ';
    s += svgNum(x) + "," + svgNum(y);
  }
  return s;
}

}  // namespace wattswath::report
