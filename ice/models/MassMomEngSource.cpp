// <Model type="mass_momentum_energy_src">: user-given volumetric rates of
// mass, momentum and energy added to one material (Vaango's
// Models/FluidsBased/MassMomEng_src; facts from its source, code our own).
//
// Per step, in every interior cell with vol_frac > 0.001 of the material,
//   dm = mass_src     dt V theta        [mass_src in kg/(m^3 s)]
//   dp = momentum_src dt V theta        [kg/(m^2 s^2), a vector]
//   dE = energy_src   dt V theta        [W/m^3]
// (theta = that material's volume fraction after equilibration), while the
// time at the start of the step lies in [mme_src_t_start, mme_src_t_final]
// (defaults 0 and 9e99). As in Vaango's current version no specific-volume
// source is added (Uintah's older version added dm v; Vaango commented it out).
// dE enters the internal energy only: to keep T fixed, energy_src must be
// mass_src cv T (Vaango's comment).
// Reductions: TotalMass_src, TotalMom_src (vector), TotalEng_src: the sums
// of dm, dp, dE over the last step (Vaango's labels).
//
// Layouts: parameters in a <MassMomEng_src> block (Vaango's code) or
// directly in <Model> (Vaango's schema, ups_spec Models.xml).
#include "core/grid/Loop.h"
#include "ice/models/ModelSupport.h"
#include "ice/models/SourceMaterials.h"

namespace tephra {

namespace {

class MassMomEngSource final : public IceModel, public SourceMaterials {
 public:
  MassMomEngSource(const DeckNode& model, const IceSetup& s) {
    ModelParams p(model_block(model, "MassMomEng_src"), "mass_momentum_energy_src");
    m_ = p.material("material", s);
    mass_rate_ = p.number("mass_src");
    mom_rate_ = p.vec3("momentum_src");
    eng_rate_ = p.number("energy_src");
    t0_ = p.number("mme_src_t_start", 0.0);
    t1_ = p.number("mme_src_t_final", 9e99);
    if (t1_ < t0_) p.node().require_child("mme_src_t_final").fail("mme_src_t_final < mme_src_t_start");
    p.finish();
  }
  std::string type() const override { return "mass_momentum_energy_src"; }
  std::vector<std::size_t> source_materials() const override { return {m_}; }
  void initialize(const Grid& g, const std::vector<IceMaterialFields>&) override { sums_.reset(g, 5); }
  std::set<std::string> labels() const override { return {"TotalMass_src", "TotalMom_src", "TotalEng_src"}; }
  // Per patch: columns 0 mass, 1 energy, 2-4 momentum (exact across MPI ranks).
  std::vector<ModelSum> patch_sums() const override {
    return {{"TotalMass_src", &sums_, 0, 1}, {"TotalEng_src", &sums_, 1, 1}, {"TotalMom_src", &sums_, 2, 3}};
  }
  std::vector<std::pair<std::string, PatchSums*>> state_sums() override { return {{"sums", &sums_}}; }
  void compute_sources(const IceModelInput& in, IceModelSources& out) override {
    sums_.zero();
    if (in.time < t0_ || in.time > t1_) return;
    const Grid& g = in.grid;
    const double Vdt = g.cell_volume() * in.dt;
    const IceMaterialFields& f = in.mats[m_];
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        const double theta = f.vol_frac_CC[pi](i, j, k);
        if (!(theta > 0.001)) return;
        const double dm = mass_rate_ * Vdt * theta, dE = eng_rate_ * Vdt * theta;
        const Vec3 dp = mom_rate_ * (Vdt * theta);
        out.mass[m_][pi](i, j, k) += dm;
        out.momentum[m_][pi](i, j, k) += dp;
        out.energy[m_][pi](i, j, k) += dE;
        sums_.at(pi, 0) += dm;
        sums_.at(pi, 1) += dE;
        for (int d = 0; d < 3; ++d) sums_.at(pi, 2 + d) += dp[d];
      });
  }

 private:
  std::size_t m_ = 0;
  double mass_rate_ = 0, eng_rate_ = 0, t0_ = 0, t1_ = 0;
  Vec3 mom_rate_ = Vec3::Zero();
  PatchSums sums_;
};

}  // namespace

IceModelP make_mass_mom_eng_src(const DeckNode& m, const IceSetup& s) { return std::make_shared<MassMomEngSource>(m, s); }

}  // namespace tephra
