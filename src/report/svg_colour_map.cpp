#include "report/svg_colour_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace drycut::report {
namespace {

struct Rgb {
  double r, g, b;
};
// A diverging red-yellow-green-blue ramp, readable on white.
constexpr std::array<Rgb, 5> kAnchors{{{178, 24, 43}, {239, 138, 98}, {214, 180, 40}, {90, 174, 97}, {33, 102, 172}}};

}  // namespace

int colour_bin(double fraction) {
  if (!(fraction > 0)) return 0;
  if (fraction >= 1) return kColourBins - 1;
  return std::min(kColourBins - 1, static_cast<int>(fraction * kColourBins));
}

std::string scale_colour(double fraction) {
  if (!(fraction > 0)) fraction = 0;
  fraction = std::min(fraction, 1.0);
  const double pos = fraction * (kAnchors.size() - 1);
  const size_t i = std::min(static_cast<size_t>(pos), kAnchors.size() - 2);
  const double f = pos - static_cast<double>(i);
  const Rgb& a = kAnchors[i];
  const Rgb& b = kAnchors[i + 1];
  auto mix = [f](double x, double y) { return static_cast<int>(std::lround(x + (y - x) * f)); };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b));
  return buf;
}

std::string bin_colour(int bin) {
  bin = std::clamp(bin, 0, kColourBins - 1);
  return scale_colour((bin + 0.5) / kColourBins);
}

}  // namespace drycut::report
