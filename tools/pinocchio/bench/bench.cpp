// Times Pinocchio's rnea, crba, aba and crba + Cholesky forward dynamics on
// the models and states that rodyn's comparison binary hands it, so that both
// libraries run the same URDFs on the same inputs.
//
// Usage: pinocchio-bench <manifest> <target milliseconds per measurement>
//        pinocchio-bench --profile <manifest> <algorithm> <model> <calls>
// (the second runs one algorithm a fixed number of times, for callgrind).
//
// The manifest has one line per model:
//   model <name> <urdf> <free_flyer 0|1> <gx> <gy> <gz> <states file>
// and a states file starts with "nq nv count", then one state per line:
//   q (nq numbers), v, a, tau (nv numbers each).
//
// Output, one line each:
//   check <name> <rnea torques of the first state>   (to prove the models agree)
//   time <name> <algorithm> <nanoseconds per call>
// Algorithms: rnea, crba_local, crba_world, crba_fd_local, crba_fd_world,
// aba_local, aba_world. Pinocchio offers both conventions; the comparison
// credits it with the faster of the two. crba times the whole symmetric
// matrix, as rodyn's crba returns it (Pinocchio computes the upper triangle
// and the caller mirrors it); the forward dynamics use the triangle alone.

#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/cholesky.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody.hpp>
#include <pinocchio/parsers/urdf.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

  struct State
  {
    Eigen::VectorXd q, v, a, tau;
  };

  struct ModelEntry
  {
    std::string name, urdf, states_file;
    bool free_flyer = false;
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  };

  // Keeps the optimiser from dropping a result it cannot see being used.
  template<typename T>
  inline void keep(const T & value)
  {
    asm volatile("" : : "g"(&value) : "memory");
  }

  std::vector<State> read_states(const std::string & path, int nq, int nv)
  {
    std::ifstream in(path);
    int file_nq = 0, file_nv = 0, count = 0;
    in >> file_nq >> file_nv >> count;
    if (!in || file_nq != nq || file_nv != nv)
      throw std::runtime_error(
        "states file " + path + " does not match the model's nq = " + std::to_string(nq)
        + ", nv = " + std::to_string(nv));
    std::vector<State> states(count);
    for (State & s : states)
    {
      s.q.resize(nq);
      s.v.resize(nv);
      s.a.resize(nv);
      s.tau.resize(nv);
      for (int k = 0; k < nq; ++k)
        in >> s.q[k];
      for (Eigen::VectorXd * vec : {&s.v, &s.a, &s.tau})
        for (int k = 0; k < nv; ++k)
          in >> (*vec)[k];
    }
    if (!in)
      throw std::runtime_error("states file " + path + " is truncated");
    return states;
  }

  // Nanoseconds per call of body(k) for `calls` calls, k cycling over the states.
  double ns_per_call(std::size_t calls, std::size_t states, const std::function<void(std::size_t)> & body)
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < calls; ++i)
      body(i % states);
    const auto stop = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::nano>(stop - start).count() / double(calls);
  }

  // Same calibration as rodyn's timing loop: probe, then size one measurement.
  double measure(double target_ns, std::size_t states, const std::function<void(std::size_t)> & body)
  {
    std::size_t calls = 16;
    for (;;)
    {
      const double per_call = ns_per_call(calls, states, body);
      if (per_call * double(calls) > 2.0e6 || calls >= (std::size_t(1) << 24))
      {
        std::size_t n = std::size_t(target_ns / std::max(per_call, 1.0));
        n = std::min(std::max(n, std::size_t(16)), std::size_t(1) << 26);
        return ns_per_call(n, states, body);
      }
      calls *= 4;
    }
  }

  // Exactly `calls` calls of one algorithm, for profilers (a timed
  // measurement picks its number of calls from the clock).
  struct ProfileRequest
  {
    std::string model, algorithm;
    std::size_t calls = 0;
  };

  // Times every algorithm on the model, or with `profile` set runs the one
  // it names.
  void run_model(const ModelEntry & entry, double target_ns, const ProfileRequest * profile)
  {
    using namespace pinocchio;
    Model model;
    if (entry.free_flyer)
      pinocchio::urdf::buildModel(entry.urdf, JointModelFreeFlyer(), model);
    else
      pinocchio::urdf::buildModel(entry.urdf, model);
    model.gravity.linear(entry.gravity);
    Data data(model);
    const std::vector<State> states = read_states(entry.states_file, model.nq, model.nv);
    const std::size_t n = states.size();


    // Pinocchio's crba fills only the upper triangle of M; rodyn's crba
    // returns the whole matrix, so the copy into the lower triangle (what
    // Pinocchio's documentation tells a caller to do, and what its Python
    // binding does) is timed with it.
    auto full_mass_matrix = [&](std::size_t k, Convention convention) {
      crba(model, data, states[k].q, convention);
      data.M.triangularView<Eigen::StrictlyLower>() =
        data.M.transpose().triangularView<Eigen::StrictlyLower>();
      keep(data.M);
    };
    Eigen::VectorXd rhs(model.nv);
    auto crba_fd = [&](std::size_t k, Convention convention) {
      const State & s = states[k];
      nonLinearEffects(model, data, s.q, s.v);
      crba(model, data, s.q, convention);
      cholesky::decompose(model, data);
      rhs = s.tau - data.nle;
      cholesky::solve(model, data, rhs);
      keep(rhs);
    };
    const std::vector<std::pair<const char *, std::function<void(std::size_t)>>> algorithms = {
      {"rnea",
       [&](std::size_t k) { keep(rnea(model, data, states[k].q, states[k].v, states[k].a)); }},
      {"crba_local", [&](std::size_t k) { full_mass_matrix(k, Convention::LOCAL); }},
      {"crba_world", [&](std::size_t k) { full_mass_matrix(k, Convention::WORLD); }},
      {"crba_fd_local", [&](std::size_t k) { crba_fd(k, Convention::LOCAL); }},
      {"crba_fd_world", [&](std::size_t k) { crba_fd(k, Convention::WORLD); }},
      {"aba_local",
       [&](std::size_t k) {
         const State & s = states[k];
         keep(aba(model, data, s.q, s.v, s.tau, Convention::LOCAL));
       }},
      {"aba_world",
       [&](std::size_t k) {
         const State & s = states[k];
         keep(aba(model, data, s.q, s.v, s.tau, Convention::WORLD));
       }},
    };
    if (profile)
    {
      for (const auto & [name, body] : algorithms)
        if (profile->algorithm == name)
        {
          for (std::size_t i = 0; i < profile->calls; ++i)
            body(i % n);
          return;
        }
      throw std::runtime_error("unknown algorithm " + profile->algorithm);
    }
    rnea(model, data, states[0].q, states[0].v, states[0].a);
    std::printf("check %s", entry.name.c_str());
    for (int k = 0; k < model.nv; ++k)
      std::printf(" %.17g", data.tau[k]);
    std::printf("\n");
    for (const auto & [name, body] : algorithms)
      std::printf("time %s %s %.3f\n", entry.name.c_str(), name, measure(target_ns, n, body));
    std::fflush(stdout);
  }

} // namespace

int main(int argc, char ** argv)
{
  const bool profiling = argc == 6 && std::string(argv[1]) == "--profile";
  if (argc != 3 && !profiling)
  {
    std::fprintf(
      stderr,
      "usage: %s <manifest> <target ms per measurement>\n"
      "       %s --profile <manifest> <algorithm> <model> <calls>\n",
      argv[0], argv[0]);
    return 2;
  }
  try
  {
    ProfileRequest request;
    if (profiling)
      request = {argv[4], argv[3], std::size_t(std::stoull(argv[5]))};
    const double target_ns = profiling ? 0.0 : std::stod(argv[2]) * 1.0e6;
    std::ifstream manifest(argv[profiling ? 2 : 1]);
    bool found = false;
    std::string line;
    while (std::getline(manifest, line))
    {
      std::istringstream fields(line);
      std::string tag;
      ModelEntry entry;
      int free_flyer = 0;
      if (!(fields >> tag) || tag != "model")
        continue;
      fields >> entry.name >> entry.urdf >> free_flyer >> entry.gravity[0] >> entry.gravity[1]
        >> entry.gravity[2] >> entry.states_file;
      if (!fields)
        throw std::runtime_error("malformed manifest line: " + line);
      entry.free_flyer = free_flyer != 0;
      if (profiling && entry.name != request.model)
        continue;
      found = true;
      run_model(entry, target_ns, profiling ? &request : nullptr);
    }
    if (!found)
      throw std::runtime_error(
        profiling ? "model " + request.model + " is not in the manifest" : "empty manifest");
  }
  catch (const std::exception & e)
  {
    std::fprintf(stderr, "pinocchio-bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
