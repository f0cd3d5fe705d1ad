#include "clouds/mie.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace planet {

MieSphere mie_sphere(double x, std::complex<double> m, const std::vector<double>& mu) {
  using C = std::complex<double>;
  if (!(x > 0)) throw InputError("mie_sphere: the size parameter must be positive");
  // Wiscombe 1980's number of terms, as Bohren and Huffman's BHMIE takes it.
  const int n_stop = int(std::lround(x + 4.0 * std::cbrt(x) + 2.0));
  const C y = m * x;
  // The logarithmic derivative D_n(mx) = psi_n'(mx) / psi_n(mx), by the
  // downward recurrence D_(n-1) = n/y - 1 / (D_n + n/y) (B&H eq. 4.89),
  // which is stable where the upward one is not; started well above the
  // terms needed.
  const int n_top = std::max(n_stop, int(std::abs(y))) + 16;
  std::vector<C> d(size_t(n_top) + 1, C(0.0));
  for (int n = n_top; n > 0; --n) d[n - 1] = double(n) / y - 1.0 / (d[n] + double(n) / y);

  // Riccati-Bessel psi_n(x) = x j_n(x) and chi_n(x) = -x y_n(x) by their
  // upward recurrence (stable for real x), from psi_(-1) = cos x,
  // psi_0 = sin x, chi_(-1) = -sin x, chi_0 = cos x; xi = psi - i chi.
  double psi_prev = std::cos(x), psi = std::sin(x);
  double chi_prev = -std::sin(x), chi = std::cos(x);
  C xi = C(psi, -chi);
  // The angular functions pi_n and tau_n per angle (B&H eqs. 4.47).
  std::vector<double> pi_prev(mu.size(), 0.0), pi_n(mu.size(), 1.0);
  std::vector<C> s1(mu.size(), 0.0), s2(mu.size(), 0.0);
  MieSphere out;
  double sum_ext = 0, sum_sca = 0, sum_g = 0;
  C a_prev(0.0), b_prev(0.0);
  for (int n = 1; n <= n_stop; ++n) {
    const double nd = n;
    const double psi_next = (2.0 * nd - 1.0) / x * psi - psi_prev;
    const double chi_next = (2.0 * nd - 1.0) / x * chi - chi_prev;
    const C xi_next(psi_next, -chi_next);
    // B&H eqs. 4.88: the coefficients from D_n and the Riccati-Bessels.
    const C da = d[n] / m + nd / x;
    const C db = m * d[n] + nd / x;
    const C a = (da * psi_next - psi) / (da * xi_next - xi);
    const C b = (db * psi_next - psi) / (db * xi_next - xi);
    sum_ext += (2.0 * nd + 1.0) * (a + b).real();
    sum_sca += (2.0 * nd + 1.0) * (std::norm(a) + std::norm(b));
    // B&H eq. 4.82 (the asymmetry parameter's two sums).
    if (n > 1) {
      sum_g +=
          (nd - 1.0) * (nd + 1.0) / nd * (a_prev * std::conj(a) + b_prev * std::conj(b)).real();
      sum_g += (2.0 * nd - 1.0) / ((nd - 1.0) * nd) * (a_prev * std::conj(b_prev)).real();
    }
    const double f = (2.0 * nd + 1.0) / (nd * (nd + 1.0));
    for (size_t j = 0; j < mu.size(); ++j) {
      const double tau = nd * mu[j] * pi_n[j] - (nd + 1.0) * pi_prev[j];
      s1[j] += f * (a * pi_n[j] + b * tau);
      s2[j] += f * (a * tau + b * pi_n[j]);
      const double pi_next = ((2.0 * nd + 1.0) * mu[j] * pi_n[j] - (nd + 1.0) * pi_prev[j]) / nd;
      pi_prev[j] = pi_n[j];
      pi_n[j] = pi_next;
    }
    psi_prev = psi;
    psi = psi_next;
    chi_prev = chi;
    chi = chi_next;
    xi = xi_next;
    a_prev = a;
    b_prev = b;
  }
  // The last term of the first sum of eq. 4.82 pairs a_N with a_(N+1) = 0.
  const double nd = n_stop;
  sum_g += (2.0 * nd + 1.0) / (nd * (nd + 1.0)) * (a_prev * std::conj(b_prev)).real();
  out.q_ext = 2.0 / (x * x) * sum_ext;
  out.q_sca = 2.0 / (x * x) * sum_sca;
  out.g = 4.0 / (x * x * out.q_sca) * sum_g;
  out.s11.resize(mu.size());
  for (size_t j = 0; j < mu.size(); ++j) out.s11[j] = 0.5 * (std::norm(s1[j]) + std::norm(s2[j]));
  return out;
}

std::vector<double> mie_phase_table(double diameter, double spread, int n, double wavelength,
                                    std::complex<double> m, const std::vector<double>& mu) {
  // The integral of (|S1|^2 + |S2|^2) / 2 over the sphere is x^2 pi Q_sca
  // (B&H eq. 3.26 with C_sca = Q_sca pi a^2 and k = x / a), so summing S11
  // and x^2 pi Q_sca over the sizes weights each by its cross-section.
  std::vector<double> sum(mu.size(), 0.0);
  double norm = 0;
  for (int i = 0; i < n; ++i) {
    double t = n == 1 ? 0.0 : 2.0 * i / (n - 1) - 1.0;
    double x = std::numbers::pi * diameter * (1.0 + spread * t) / wavelength;
    MieSphere s = mie_sphere(x, m, mu);
    for (size_t j = 0; j < mu.size(); ++j) sum[j] += s.s11[j];
    norm += std::numbers::pi * x * x * s.q_sca;
  }
  for (double& v : sum) v /= norm;
  return sum;
}

}  // namespace planet
