// Rough crack faces: one memory diagram per contact cell with one tangential
// component (2D); with two (3D) the MMD's 3D rule, a vector spring bed per cell
// (PHYSICS.md §3.5, spring_bed_vector.hpp).
#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"
#include "vibrotherm/contact/spring_bed_vector.hpp"

namespace vibrotherm::contact {
namespace {

class MmdLaw final : public CrackLaw {
 public:
  MmdLaw(std::unique_ptr<NormalLaw> law, const MmdConfig& cfg, const SpringBedConfig& bed_cfg)
      : law_(std::move(law)), cfg_(cfg), bed_cfg_(bed_cfg) {}
  std::string name() const override { return "mmd"; }
  void initialize(std::size_t cells, const double* a, const Tangential* b) override {
    vector_ = cells > 0 && b[0].components() == 2;
    if (vector_) return initialize_beds(cells, a, b);
    diagrams_.assign(cells, MemoryDiagram{});
    for (std::size_t i = 0; i < cells; ++i) diagrams_[i].reset(*law_, a[i], b[i][0]);
  }
  std::size_t cells() const override { return vector_ ? beds_.size() : diagrams_.size(); }
  Traction trial(std::size_t cell, double a, const Tangential& b) const override {
    if (vector_) return beds_[cell].trial(*law_, bed_cfg_, a, b);
    return diagrams_[cell].trial(*law_, cfg_, a, b[0]);
  }
  StepResult commit(std::size_t cell, double a, const Tangential& b) override {
    if (vector_) return beds_[cell].commit(*law_, bed_cfg_, a, b);
    return diagrams_[cell].commit(*law_, cfg_, a, b[0]);
  }
  double stored_energy(std::size_t cell) const override {
    if (vector_) return beds_[cell].stored_energy(*law_, bed_cfg_);
    return diagrams_[cell].stored_energy(cfg_);
  }
  Tangential slip_offset(std::size_t cell) const override {
    if (vector_) return beds_[cell].slip_offset();
    return Tangential(diagrams_[cell].b0());
  }
  CellStiffness stiffness(std::size_t, double a) const override {
    // All springs stuck: dT/db = N'(a)/θ <= dN/da.
    const double k = a > 0.0 ? law_->eval(a).dN : law_->stiffness_at_zero();
    return {k, k / cfg_.theta};
  }
  bool can_dissipate() const override { return cfg_.mu > 0.0; }
  double friction_bound() const override { return cfg_.mu; }
  bool has_contact() const override { return true; }
  std::vector<double> save_state(std::size_t cell) const override {
    return vector_ ? beds_[cell].save() : diagrams_[cell].save();
  }
  void restore_state(std::size_t cell, const double* v, std::size_t n) override {
    if (vector_) beds_[cell].restore(*law_, v, n);
    else diagrams_[cell].restore(v, n);
  }

 private:
  void initialize_beds(std::size_t cells, const double* a, const Tangential* b) {
    beds_.assign(cells, VectorSpringBed{});
    for (std::size_t i = 0; i < cells; ++i) {
      if (b[i].components() != 2) throw InputError("-crack_law mmd: cells with 1 and 2 tangential components mixed");
      beds_[i].reset(*law_, bed_cfg_, a[i], b[i]);
    }
  }

  std::unique_ptr<NormalLaw> law_;
  MmdConfig cfg_;
  SpringBedConfig bed_cfg_;
  bool vector_ = false;                ///< two tangential components: the vector spring bed
  std::vector<MemoryDiagram> diagrams_;  ///< one component (2D): the memory diagram
  std::vector<VectorSpringBed> beds_;
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
      integer_parameter("-crack_mmd_levels", &P::mmd_levels, "256", Range::between(2, 1e6),
                        "mmd crack law, two tangential components (3D): the most spring-bed levels per cell "
                        "(2 numbers each)"),
  };
  return list;
}

std::unique_ptr<CrackLaw> create_mmd_law(const ContactParameters& params) {
  const MmdConfig cfg{params.mu, params.theta(), params.mmd_rel_tol,
                      static_cast<std::size_t>(params.mmd_max_breakpoints)};
  const SpringBedConfig bed_cfg{params.mu, params.theta(), params.mmd_levels};
  return std::make_unique<MmdLaw>(create_normal_law(params), cfg, bed_cfg);
}

}  // namespace vibrotherm::contact
