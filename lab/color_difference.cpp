#include "lab/color_difference.h"

#include "core/error.h"

#include <cmath>

namespace planet {

namespace {

constexpr double kPi = 3.14159265358979323846;

double linear_from_srgb(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double lab_f(double t) {
  constexpr double e = 216.0 / 24389.0, k = 24389.0 / 27.0;
  return t > e ? std::cbrt(t) : (k * t + 16.0) / 116.0;
}

double degrees(double radians) { return radians * 180.0 / kPi; }
double radians(double degrees) { return degrees * kPi / 180.0; }

}  // namespace

Lab lab_from_srgb8(uint8_t r8, uint8_t g8, uint8_t b8) {
  double r = linear_from_srgb(r8 / 255.0), g = linear_from_srgb(g8 / 255.0),
         b = linear_from_srgb(b8 / 255.0);
  // sRGB's primaries to XYZ, D65, and XYZ over the white point.
  double x = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
  double y = (0.2126729 * r + 0.7151522 * g + 0.0721750 * b) / 1.0;
  double z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
  double fx = lab_f(x), fy = lab_f(y), fz = lab_f(z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab& one, const Lab& two) {
  const double L1 = one[0], a1 = one[1], b1 = one[2];
  const double L2 = two[0], a2 = two[1], b2 = two[2];
  double C1 = std::hypot(a1, b1), C2 = std::hypot(a2, b2);
  double C_mean = 0.5 * (C1 + C2);
  double C7 = std::pow(C_mean, 7.0);
  double G = 0.5 * (1.0 - std::sqrt(C7 / (C7 + std::pow(25.0, 7.0))));
  double a1p = (1.0 + G) * a1, a2p = (1.0 + G) * a2;
  double C1p = std::hypot(a1p, b1), C2p = std::hypot(a2p, b2);
  auto hue = [](double b, double a) {
    if (a == 0.0 && b == 0.0) return 0.0;
    double h = degrees(std::atan2(b, a));
    return h < 0.0 ? h + 360.0 : h;
  };
  double h1p = hue(b1, a1p), h2p = hue(b2, a2p);
  double dLp = L2 - L1, dCp = C2p - C1p;
  double dhp = 0.0;
  if (C1p * C2p != 0.0) {
    dhp = h2p - h1p;
    if (dhp > 180.0) dhp -= 360.0;
    if (dhp < -180.0) dhp += 360.0;
  }
  double dHp = 2.0 * std::sqrt(C1p * C2p) * std::sin(radians(0.5 * dhp));
  double Lp_mean = 0.5 * (L1 + L2), Cp_mean = 0.5 * (C1p + C2p);
  double hp_mean = h1p + h2p;
  if (C1p * C2p != 0.0) {
    if (std::abs(h1p - h2p) <= 180.0) {
      hp_mean *= 0.5;
    } else {
      hp_mean = h1p + h2p < 360.0 ? 0.5 * (h1p + h2p + 360.0) : 0.5 * (h1p + h2p - 360.0);
    }
  }
  double T = 1.0 - 0.17 * std::cos(radians(hp_mean - 30.0)) + 0.24 * std::cos(radians(2.0 * hp_mean)) +
             0.32 * std::cos(radians(3.0 * hp_mean + 6.0)) -
             0.20 * std::cos(radians(4.0 * hp_mean - 63.0));
  double d_theta = 30.0 * std::exp(-std::pow((hp_mean - 275.0) / 25.0, 2.0));
  double Cp7 = std::pow(Cp_mean, 7.0);
  double R_C = 2.0 * std::sqrt(Cp7 / (Cp7 + std::pow(25.0, 7.0)));
  double L50 = (Lp_mean - 50.0) * (Lp_mean - 50.0);
  double S_L = 1.0 + 0.015 * L50 / std::sqrt(20.0 + L50);
  double S_C = 1.0 + 0.045 * Cp_mean;
  double S_H = 1.0 + 0.015 * Cp_mean * T;
  double R_T = -std::sin(radians(2.0 * d_theta)) * R_C;
  double l = dLp / S_L, c = dCp / S_C, h = dHp / S_H;
  return std::sqrt(l * l + c * c + h * h + R_T * c * h);
}

double mean_ciede2000(const std::vector<uint8_t>& one, const std::vector<uint8_t>& two,
                      const std::vector<uint8_t>& mask) {
  if (one.size() != two.size() || one.size() % 3 != 0) {
    throw InputError("images of different sizes cannot be compared");
  }
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < one.size() / 3; ++i) {
    if (!mask.empty() && mask[i]) continue;
    sum += ciede2000(lab_from_srgb8(one[3 * i], one[3 * i + 1], one[3 * i + 2]),
                     lab_from_srgb8(two[3 * i], two[3 * i + 1], two[3 * i + 2]));
    ++n;
  }
  return n ? sum / double(n) : 0.0;
}

}  // namespace planet
