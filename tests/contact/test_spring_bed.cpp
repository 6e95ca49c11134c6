// Requirement: the memory diagram is the exact continuum limit of a bed of
// independent Jenkins spring-sliders (PHYSICS.md §3.3, "physical picture").
// An independent brute-force bed of 20000 discrete springs, stepped finely,
// must agree on T and on the dissipated energy for a combined history.
#include <gtest/gtest.h>

#include "contact_test_support.hpp"

namespace vibrotherm::contact {
namespace {

/// Springs α_i with weight dN' on [α_i − h/2, α_i + h/2] (and the atom N'(0+)
/// at α = 0); each a Jenkins element with limit θμ(a − α) on its elastic part.
class SpringBed {
 public:
  SpringBed(const NormalLaw& law, double theta, double mu, double alpha_max, int count)
      : theta_(theta), mu_(mu) {
    const double h = alpha_max / count;
    alpha_.push_back(0.0);
    weight_.push_back(law.stiffness_at_zero());
    for (int i = 0; i < count; ++i) {
      const double x = (i + 0.5) * h;
      alpha_.push_back(x);
      weight_.push_back(law.eval(x + 0.5 * h).dN - law.eval(std::max(x - 0.5 * h, 0.0)).dN);
    }
    anchor_.assign(alpha_.size(), 0.0);
    touching_.assign(alpha_.size(), false);
  }
  /// Moves to (a, b); springs touch when a passes α, anchored where they touch.
  double step(double a_old, double a, double b) {
    double dW = 0.0;
    const double a_mid = 0.5 * (a_old + a);
    for (std::size_t i = 0; i < alpha_.size(); ++i) {
      if (!(a > alpha_[i]) || (alpha_[i] == 0.0 && !(a > 0.0))) {
        touching_[i] = false;
        continue;
      }
      if (!touching_[i]) {
        touching_[i] = true;
        anchor_[i] = b;
      }
      const double lim = theta_ * mu_ * (a - alpha_[i]);
      const double p = std::clamp(anchor_[i], b - lim, b + lim);
      dW += 2.0 * mu_ * std::max(a_mid - alpha_[i], 0.0) * weight_[i] * std::abs(p - anchor_[i]);
      anchor_[i] = p;
    }
    return dW;
  }
  double T(double b) const {
    double t = 0.0;
    for (std::size_t i = 0; i < alpha_.size(); ++i)
      if (touching_[i]) t += weight_[i] * (b - anchor_[i]);
    return t / theta_;
  }

 private:
  double theta_, mu_;
  std::vector<double> alpha_, weight_, anchor_;
  std::vector<bool> touching_;
};

TEST(SpringBedReference, CombinedHistoryAgrees) {
  for (const char* normal : {"biwa", "power"}) {
    ContactParameters p;
    p.mu = 0.7;
    p.normal_law = normal;
    if (p.normal_law == "power") p.power_C = 1e18;
    const auto law = create_normal_law(p);
    const double s = 1e-8, tm = p.theta() * p.mu;
    auto path = [&](double t, double& a, double& b) {
      a = s * (0.6 + 0.5 * std::sin(2 * M_PI * t + 0.5) + 0.2 * t);
      b = tm * s * (0.7 * std::sin(2 * M_PI * t) + 0.2 * std::sin(6 * M_PI * t));
    };
    SpringBed bed(*law, p.theta(), p.mu, 1.6 * s, 20000);
    double a, b;
    path(0.0, a, b);
    auto mmd = testing::one_cell(p, a, b);
    bed.step(a, a, b);
    const int coarse = 400, fine = 40;  // the bed takes 40 substeps per MMD step
    double W_mmd = 0.0, W_bed = 0.0, max_T = 0.0, max_dT = 0.0;
    for (int k = 1; k <= 2 * coarse; ++k) {
      double a_prev = a;
      for (int j = 1; j <= fine; ++j) {
        path((k - 1.0 + double(j) / fine) / coarse, a, b);
        W_bed += bed.step(a_prev, a, b);
        a_prev = a;
      }
      const StepResult r = mmd->commit(0, a, Tangential(b));
      W_mmd += r.dW;
      max_T = std::max(max_T, std::abs(r.T[0]));
      max_dT = std::max(max_dT, std::abs(r.T[0] - bed.T(b)));
    }
    EXPECT_LT(max_dT, 2e-3 * max_T) << normal;
    EXPECT_NEAR(W_mmd, W_bed, 3e-3 * W_bed) << normal;
  }
}

}  // namespace
}  // namespace vibrotherm::contact
