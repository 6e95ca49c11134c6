// Rough crack faces: one memory diagram per contact cell. One tangential
// component only: the 3D rule (a vector spring bed, PHYSICS.md §3.5) comes with 3D.
#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

class MmdLaw final : public CrackLaw {
 public:
  MmdLaw(std::unique_ptr<NormalLaw> law, const MmdConfig& cfg) : law_(std::move(law)), cfg_(cfg) {}
  std::string name() const override { return "mmd"; }
  void initialize(std::size_t cells, const double* a, const Tangential* b) override {
    diagrams_.assign(cells, MemoryDiagram{});
    for (std::size_t i = 0; i < cells; ++i) {
      if (b[i].components() != 1)
        throw InputError("-crack_law mmd: two tangential components (3D) are not implemented yet; "
                         "use -crack_law coulomb, linear or clapping");
      diagrams_[i].reset(*law_, a[i], b[i][0]);
    }
  }
  std::size_t cells() const override { return diagrams_.size(); }
  Traction trial(std::size_t cell, double a, const Tangential& b) const override {
    return diagrams_[cell].trial(*law_, cfg_, a, b[0]);
  }
  StepResult commit(std::size_t cell, double a, const Tangential& b) override {
    return diagrams_[cell].commit(*law_, cfg_, a, b[0]);
  }
  double stored_energy(std::size_t cell) const override { return diagrams_[cell].stored_energy(cfg_); }
  Tangential slip_offset(std::size_t cell) const override { return Tangential(diagrams_[cell].b0()); }
  CellStiffness stiffness(std::size_t, double a) const override {
    // All springs stuck: dT/db = N'(a)/θ <= dN/da.
    const double k = a > 0.0 ? law_->eval(a).dN : law_->stiffness_at_zero();
    return {k, k / cfg_.theta};
  }
  bool can_dissipate() const override { return cfg_.mu > 0.0; }
  double friction_bound() const override { return cfg_.mu; }
  bool has_contact() const override { return true; }
  std::vector<double> save_state(std::size_t cell) const override { return diagrams_[cell].save(); }
  void restore_state(std::size_t cell, const double* v, std::size_t n) override { diagrams_[cell].restore(v, n); }

  const MemoryDiagram& diagram(std::size_t cell) const { return diagrams_[cell]; }

 private:
  std::unique_ptr<NormalLaw> law_;
  MmdConfig cfg_;
  std::vector<MemoryDiagram> diagrams_;
};

}  // namespace

const ContactParameterList& mmd_law_parameters() {
  using P = ContactParameters;
  // -material_nu is the simulator's material option: one Poisson ratio for the
  // elastic waves and for θ. The default matches wave::ElasticMaterial's.
  static const ContactParameterList list = {
      real_parameter("-material_nu", &P::nu, "0.33", Range::open(-1.0, 0.5), "",
                     "mmd crack law: the material's Poisson ratio, for Mindlin's theta = (2 - nu)/(2 (1 - nu))"),
      real_parameter("-crack_mmd_tol", &P::mmd_rel_tol, "1e-14", Range::open(0.0, 1e-2), "",
                     "mmd crack law: shortest kept memory-diagram segment, relative to a"),
      integer_parameter("-crack_mmd_max_breakpoints", &P::mmd_max_breakpoints, "1024", Range::between(3, 1e7),
                        "mmd crack law: hard bound on the memory-diagram breakpoints per cell"),
  };
  return list;
}

std::unique_ptr<CrackLaw> create_mmd_law(const ContactParameters& params) {
  const MmdConfig cfg{params.mu, params.theta(), params.mmd_rel_tol,
                      static_cast<std::size_t>(params.mmd_max_breakpoints)};
  return std::make_unique<MmdLaw>(create_normal_law(params), cfg);
}

}  // namespace vibrotherm::contact
