// Pinocchio's time per call of the kinematics-for-control algorithms, as
// `model algorithm ns` lines beside rodyn's (`kinematics_timing`); built and
// run by compare_kinematics.sh with the flags of bench.cpp.
#include <pinocchio/algorithm/centroidal.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
  double ns_per_call(std::size_t calls, std::size_t states, const std::function<void(std::size_t)> & body)
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < calls; ++i)
      body(i % states);
    const auto stop = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(stop - start).count() / double(calls);
  }

  // The calibration of rodyn-bench's timing loop, median of five runs.
  double time(double ms, std::size_t states, const std::function<void(std::size_t)> & body)
  {
    std::size_t calls = 16;
    for (;;)
    {
      const double per_call = ns_per_call(calls, states, body);
      if (per_call * double(calls) > 2.0e6 || calls >= (std::size_t(1) << 24))
      {
        std::size_t n = std::size_t(ms * 1e6 / std::max(per_call, 1.0));
        n = std::min(std::max(n, std::size_t(16)), std::size_t(1) << 26);
        std::vector<double> runs;
        for (int r = 0; r < 5; ++r)
          runs.push_back(ns_per_call(n, states, body));
        std::sort(runs.begin(), runs.end());
        return runs[2];
      }
      calls *= 4;
    }
  }

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
