// Pinocchio's time per call of the kinematics-for-control algorithms, as
// `model algorithm ns` lines beside rodyn's (`kinematics_timing`); built and
// run by compare_suite.sh with the flags of bench.cpp.
#include <pinocchio/algorithm/centroidal.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
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
    std::srand(0x4B1E);
    std::vector<Eigen::VectorXd> qs, vs;
    const Eigen::VectorXd lo = -3.0 * Eigen::VectorXd::Ones(model.nq), hi = -lo;
    for (int k = 0; k < 64; ++k)
    {
      qs.push_back(randomConfiguration(model, lo, hi));
      vs.push_back(Eigen::VectorXd::Random(model.nv));
    }
    const JointIndex last = JointIndex(model.njoints - 1);
    const FrameIndex frame = model.addFrame(Frame("bench", last, SE3::Identity(), FrameType::OP_FRAME));
    data = Data(model);
    Data::Matrix6x J = Data::Matrix6x::Zero(6, model.nv);

    std::printf("%s joint_jacobians %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t k) {
      computeJointJacobians(model, data, qs[k]);
    }));
    computeJointJacobians(model, data, qs[0]);
    std::printf("%s frame_jacobian %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t) {
      J.setZero();
      getFrameJacobian(model, data, frame, LOCAL, J);
    }));
    std::printf("%s centroidal_map %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t k) {
      computeCentroidalMap(model, data, qs[k]);
    }));
    std::printf("%s ccrba %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t k) {
      ccrba(model, data, qs[k], vs[k]);
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
