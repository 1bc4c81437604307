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

  // The from-q frame Jacobians (LOCAL_WORLD_ALIGNED): one frame's
  // `computeFrameJacobian`, and, when four frames are named, the four one
  // after another (`feet_jacobians`). With no names, a frame at the last
  // joint.
  void run_frames(
    const std::string & name,
    const pinocchio::Model & model_in,
    const std::vector<std::string> & frame_names,
    double ms)
  {
    using namespace pinocchio;
    Model model = model_in;
    std::srand(0x4B1E);
    std::vector<Eigen::VectorXd> qs;
    const Eigen::VectorXd lo = -3.0 * Eigen::VectorXd::Ones(model.nq), hi = -lo;
    for (int k = 0; k < 64; ++k)
      qs.push_back(randomConfiguration(model, lo, hi));
    std::vector<FrameIndex> frames;
    if (frame_names.empty())
      frames.push_back(model.addFrame(
        Frame("bench_chain", JointIndex(model.njoints - 1), SE3::Identity(), FrameType::OP_FRAME)));
    for (const auto & f : frame_names)
      frames.push_back(model.getFrameId(f));
    Data data(model);
    Data::Matrix6x J = Data::Matrix6x::Zero(6, model.nv);
    std::printf(
      "%s frame_jacobian_from_q %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t k) {
        J.setZero();
        computeFrameJacobian(model, data, qs[k], frames[0], LOCAL_WORLD_ALIGNED, J);
      }));
    if (frames.size() == 4)
    {
      std::vector<Data::Matrix6x> Js(4, Data::Matrix6x::Zero(6, model.nv));
      std::printf(
        "%s feet_jacobians %.1f\n", name.c_str(), time(ms, qs.size(), [&](std::size_t k) {
          for (int f = 0; f < 4; ++f)
          {
            Js[f].setZero();
            computeFrameJacobian(model, data, qs[k], frames[f], LOCAL_WORLD_ALIGNED, Js[f]);
          }
        }));
    }
  }

  pinocchio::Model load(const std::string & path, bool free_flyer)
  {
    pinocchio::Model model;
    if (free_flyer)
      pinocchio::urdf::buildModel(path, pinocchio::JointModelFreeFlyer(), model);
    else
      pinocchio::urdf::buildModel(path, model);
    return model;
  }

  void run(
    const std::string & name,
    const std::string & path,
    bool free_flyer,
    const std::vector<std::string> & frame_names,
    double ms)
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
    run_frames(name, load(path, free_flyer), frame_names, ms);
  }
} // namespace

// argv: [ms] [ANYmal URDF] [G1 URDF] [Talos URDF] (example-robot-data's,
// as compare_suite.sh finds them; the frame robots are left out without).
int main(int argc, char ** argv)
{
  const double ms = argc > 1 ? std::atof(argv[1]) : 50.0;
  run("ur5", "models/urdf/ur5.urdf", false, {}, ms);
  run("panda", "models/urdf/panda.urdf", false, {}, ms);
  run("solo12", "models/urdf/solo12.urdf", true, {"FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"}, ms);
  if (argc > 4)
  {
    // The frames of host-tests/fixtures/frame_chain/, in its order.
    run_frames("anymal", load(argv[2], true), {"LF_FOOT", "RF_FOOT", "LH_FOOT", "RH_FOOT"}, ms);
    run_frames("g1", load(argv[3], true), {"left_rubber_hand"}, ms);
    run_frames("talos", load(argv[4], true), {"gripper_left_base_link"}, ms);
  }
  return 0;
}
