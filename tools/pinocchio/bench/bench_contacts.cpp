// Pinocchio's time per call of constraintDynamics, as `model algorithm ns`
// lines beside rodyn's (`contacts_timing`); built and run by
// compare_suite.sh with the flags of bench.cpp. Solo12 with its four feet
// as CONTACT_3D (LOCAL_WORLD_ALIGNED), Talos (talos_reduced.urdf, path in
// argv[2]) with both soles as CONTACT_6D (LOCAL); no Baumgarte gains, one
// proximal iteration with mu = 0: the exact KKT solve, as rodyn's.
// constraintDynamics is marked deprecated in 4.1 ("the API will change"):
// it is still the call that solves the same system as rodyn's.
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#include <pinocchio/algorithm/constrained-dynamics.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "bench_timing.hpp"

namespace
{
  using bench::time;

  void run(
    const std::string & name,
    const std::string & algorithm,
    const std::string & path,
    const std::vector<std::string> & frames,
    pinocchio::ContactType type,
    pinocchio::ReferenceFrame reference,
    double ms)
  {
    using namespace pinocchio;
    Model model;
    pinocchio::urdf::buildModel(path, JointModelFreeFlyer(), model);
    Data data(model);
    PINOCCHIO_STD_VECTOR_WITH_EIGEN_ALLOCATOR(RigidConstraintModel) constraints;
    for (const auto & frame_name : frames)
    {
      const Frame & frame = model.frames[model.getFrameId(frame_name)];
      constraints.push_back(RigidConstraintModel(
        type, model, frame.parentJoint, frame.placement, 0, SE3::Identity(), reference));
    }
    PINOCCHIO_STD_VECTOR_WITH_EIGEN_ALLOCATOR(RigidConstraintData) datas;
    for (const auto & c : constraints)
      datas.push_back(RigidConstraintData(c));
    initConstraintDynamics(model, data, constraints, datas);
    ProximalSettings settings(1e-12, 0.0, 1);
    std::srand(0xC0C7);
    std::vector<Eigen::VectorXd> qs, vs, taus;
    const Eigen::VectorXd lo = -3.0 * Eigen::VectorXd::Ones(model.nq), hi = -lo;
    for (int k = 0; k < 64; ++k)
    {
      qs.push_back(randomConfiguration(model, lo, hi));
      vs.push_back(Eigen::VectorXd::Random(model.nv));
      taus.push_back(Eigen::VectorXd::Random(model.nv));
    }
    std::printf(
      "%s %s %.1f\n", name.c_str(), algorithm.c_str(), time(ms, qs.size(), [&](std::size_t k) {
        constraintDynamics(model, data, qs[k], vs[k], taus[k], constraints, datas, settings);
      }));
  }
} // namespace

int main(int argc, char ** argv)
{
  using pinocchio::ContactType;
  using pinocchio::ReferenceFrame;
  const double ms = argc > 1 ? std::atof(argv[1]) : 50.0;
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: bench_contacts MS TALOS_URDF\n");
    return 2;
  }
  run(
    "solo12", "constrained_4_points", "models/urdf/solo12.urdf",
    {"FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"}, ContactType::CONTACT_3D,
    ReferenceFrame::LOCAL_WORLD_ALIGNED, ms);
  run(
    "talos", "constrained_2_soles", argv[2], {"left_sole_link", "right_sole_link"},
    ContactType::CONTACT_6D, ReferenceFrame::LOCAL, ms);
  return 0;
}
