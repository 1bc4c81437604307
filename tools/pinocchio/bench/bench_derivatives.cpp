// Pinocchio's time per call of the analytic derivatives of RNEA and ABA, as
// `model algorithm ns` lines beside rodyn's (`derivatives_timing`); built
// and run by compare_suite.sh with the flags of bench.cpp.
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "bench_timing.hpp"

namespace
{
  using bench::time;

  void run(const std::string & name, const std::string & path, bool free_flyer, double ms)
  {
    using namespace pinocchio;
    Model model;
    if (free_flyer)
      pinocchio::urdf::buildModel(path, JointModelFreeFlyer(), model);
    else
      pinocchio::urdf::buildModel(path, model);
    Data data(model);
    std::srand(0xDE1F);
    std::vector<Eigen::VectorXd> qs, vs, as;
    const Eigen::VectorXd lo = -3.0 * Eigen::VectorXd::Ones(model.nq), hi = -lo;
    for (int k = 0; k < 64; ++k)
    {
      qs.push_back(randomConfiguration(model, lo, hi));
      vs.push_back(Eigen::VectorXd::Random(model.nv));
      as.push_back(Eigen::VectorXd::Random(model.nv));
    }
    std::printf("%s rnea_derivatives %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t k) {
      computeRNEADerivatives(model, data, qs[k], vs[k], as[k]);
    }));
    // `as` doubles as the torques: forward dynamics' cost does not depend on them.
    std::printf("%s aba_derivatives %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t k) {
      computeABADerivatives(model, data, qs[k], vs[k], as[k]);
    }));
  }
} // namespace

int main(int argc, char ** argv)
{
  const double ms = argc > 1 ? std::atof(argv[1]) : 50.0;
  run("ur5", "models/urdf/ur5.urdf", false, ms);
  run("panda", "models/urdf/panda.urdf", false, ms);
  run("solo12", "models/urdf/solo12.urdf", true, ms);
  return 0;
}
